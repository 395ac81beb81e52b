#include "vtkMedialContractionSkeleton.h"

#include "MedialMeshData.h"
#include "MedialSkeletonData.h"
#include "contraction/SkeletonByContraction.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

vtkStandardNewMacro(vtkMedialContractionSkeleton);

namespace {
const int kStageCount = 8;
const char* const kStages[kStageCount] = {"decimation", "contraction", "factorization", "surgery",
                                          "refinement", "selection",   "radii",         "weights"};
}

vtkMedialContractionSkeleton::vtkMedialContractionSkeleton() { this->SetNumberOfOutputPorts(2); }

void vtkMedialContractionSkeleton::SetSolver(const std::string& name) {
  medial::SparseSolverKind kind;
  if (!medial::parseSparseSolverKind(name, kind)) {
    vtkErrorMacro(<< "unknown solver '" << name << "'");
    return;
  }
  if (name != this->Solver) {
    this->Solver = name;
    this->Modified();
  }
}

double vtkMedialContractionSkeleton::GetStageSeconds(const std::string& stage) const {
  for (int s = 0; s < kStageCount; ++s)
    if (stage == kStages[s]) return this->Seconds[s];
  return 0;
}

void vtkMedialContractionSkeleton::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetNodes: " << this->TargetNodes << "\n";
  os << indent << "ContractionVertices: " << this->ContractionVertices << "\n";
  os << indent << "InitialContractionFactor: " << this->InitialContractionFactor << "\n";
  os << indent << "ContractionScale: " << this->ContractionScale << "\n";
  os << indent << "MaxContractionWeight: " << this->MaxContractionWeight << "\n";
  os << indent << "MaxAttractionWeight: " << this->MaxAttractionWeight << "\n";
  os << indent << "MaxIterations: " << this->MaxIterations << "\n";
  os << indent << "ShapeWeight: " << this->ShapeWeight << "\n";
  os << indent << "SamplingWeight: " << this->SamplingWeight << "\n";
  os << indent << "RefineEmbedding: " << this->RefineEmbedding << "\n";
  os << indent << "RestoreCycles: " << this->RestoreCycles << "\n";
  os << indent << "ComputeWeights: " << this->ComputeWeights << "\n";
  os << indent << "HeatConstant: " << this->HeatConstant << "\n";
  os << indent << "Solver: " << this->Solver << "\n";
}


int vtkMedialContractionSkeleton::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                              vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* skeletonOutput = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* meshOutput = vtkPolyData::GetData(outputVector, 1);
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0) {
    vtkErrorMacro(<< "the input has no polygons: a surface mesh is needed");
    return 0;
  }

  auto triangulate = vtkSmartPointer<vtkTriangleFilter>::New();
  triangulate->SetInputData(input);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkPolyData* triangles = triangulate->GetOutput();
  const medial::TriangleMesh mesh = medial::toTriangleMesh(triangles);

  medial::SkeletonByContractionParameters p;
  p.targetNodes = this->TargetNodes;
  p.contractionVertices = this->ContractionVertices;
  p.refineEmbedding = this->RefineEmbedding;
  p.restoreCycles = this->RestoreCycles;
  p.contraction.initialContractionFactor = this->InitialContractionFactor;
  p.contraction.contractionScale = this->ContractionScale;
  p.contraction.maxContractionWeight = this->MaxContractionWeight;
  p.contraction.maxAttractionWeight = this->MaxAttractionWeight;
  p.contraction.maxIterations = this->MaxIterations;
  medial::parseSparseSolverKind(this->Solver, p.contraction.solver);
  p.surgery.shapeWeight = this->ShapeWeight;
  p.surgery.samplingWeight = this->SamplingWeight;
  p.computeWeights = this->ComputeWeights;
  p.weights.heatConstant = this->HeatConstant;
  p.weights.solver = p.contraction.solver;

  const medial::SkeletonByContractionResult result = medial::skeletonByContraction(mesh, p, [this](double f) {
    this->UpdateProgress(f);
    return !this->GetAbortExecute();
  });
  this->ContractionIterations = result.contractionIterations;
  this->CurveSkeletonNodes = result.curveSkeletonNodes;
  this->ContractedVertices = result.contractedVertices;
  this->Genus = result.cycleRepair.genus;
  this->RestoredCycles = result.cycleRepair.cyclesAdded;
  const double seconds[kStageCount] = {result.decimationSeconds, result.contractionSeconds, result.factorizationSeconds,
                                      result.surgerySeconds,     result.refinementSeconds,
                                      result.selectionSeconds,   result.radiiSeconds,
                                      result.weightsSeconds};
  std::copy(seconds, seconds + kStageCount, this->Seconds);
  if (!result.ok()) {
    vtkErrorMacro(<< result.error);
    return 0;
  }

  skeletonOutput->ShallowCopy(medial::polyDataFromSkeleton(result.skeleton));
  meshOutput->ShallowCopy(triangles);
  auto nodes = vtkSmartPointer<vtkIntArray>::New();
  nodes->SetName("SkeletonNode");
  nodes->SetNumberOfValues(triangles->GetNumberOfPoints());
  for (vtkIdType i = 0; i < triangles->GetNumberOfPoints(); ++i) nodes->SetValue(i, result.vertexToNode[size_t(i)]);
  meshOutput->GetPointData()->AddArray(nodes);
  if (this->ComputeWeights) {
    auto weights = vtkSmartPointer<vtkDoubleArray>::New();
    weights->SetName("SkinWeights");
    weights->SetNumberOfComponents(int(result.weights.cols()));
    weights->SetNumberOfTuples(result.weights.rows());
    for (Eigen::Index v = 0; v < result.weights.rows(); ++v)
      for (Eigen::Index bone = 0; bone < result.weights.cols(); ++bone)
        weights->SetTypedComponent(v, int(bone), result.weights(v, bone));
    meshOutput->GetPointData()->AddArray(weights);
  }
  return 1;
}
