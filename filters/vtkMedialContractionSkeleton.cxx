#include "vtkMedialContractionSkeleton.h"

#include "MedialProgress.h"
#include "MedialMeshData.h"
#include "MedialSkeletonData.h"
#include "common/NameList.h"
#include "contraction/SkeletonByContraction.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkStringArray.h>
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
}  // namespace

vtkMedialContractionSkeleton::vtkMedialContractionSkeleton() {
  this->SetNumberOfOutputPorts(2);
  const medial::SkeletonByContractionParameters defaults;
  this->TargetNodes = defaults.targetNodes;
  this->ContractionVertices = defaults.contractionVertices;
  this->ReferenceVertices = defaults.contraction.referenceVertices;
  this->InitialContractionFactor = defaults.contraction.initialContractionFactor;
  this->ContractionScale = defaults.contraction.contractionScale;
  this->MaxContractionWeight = defaults.contraction.maxContractionWeight;
  this->MaxAttractionWeight = defaults.contraction.maxAttractionWeight;
  this->MaxIterations = defaults.contraction.maxIterations;
  this->ShapeWeight = defaults.surgery.shapeWeight;
  this->SamplingWeight = defaults.surgery.samplingWeight;
  this->CollapseLengthFraction = defaults.surgery.deltaFraction;
  this->InitialAttractionWeight = defaults.contraction.initialAttraction;
  this->RefineEmbedding = defaults.refineEmbedding;
  this->RestoreCycles = defaults.restoreCycles;
  this->CenterNodes = defaults.centerNodes;
  this->ComputeWeights = defaults.computeWeights;
  this->HeatConstant = defaults.weights.heatConstant;
  this->Solver = medial::sparseSolverName(defaults.contraction.solver);
}

medial::SkeletonByContractionParameters vtkMedialContractionSkeleton::MakeParameters() const {
  medial::SkeletonByContractionParameters p;
  p.targetNodes = this->TargetNodes;
  p.contractionVertices = this->ContractionVertices;
  p.contraction.referenceVertices = this->ReferenceVertices;
  p.contraction.initialContractionFactor = this->InitialContractionFactor;
  p.contraction.contractionScale = this->ContractionScale;
  p.contraction.maxContractionWeight = this->MaxContractionWeight;
  p.contraction.maxAttractionWeight = this->MaxAttractionWeight;
  p.contraction.maxIterations = this->MaxIterations;
  p.surgery.shapeWeight = this->ShapeWeight;
  p.surgery.samplingWeight = this->SamplingWeight;
  p.surgery.deltaFraction = this->CollapseLengthFraction;
  p.contraction.initialAttraction = this->InitialAttractionWeight;
  p.refineEmbedding = this->RefineEmbedding;
  p.restoreCycles = this->RestoreCycles;
  p.centerNodes = this->CenterNodes;
  p.computeWeights = this->ComputeWeights;
  p.weights.heatConstant = this->HeatConstant;
  medial::parseSparseSolverKind(this->Solver, p.contraction.solver);  // SetSolver accepts known names only
  p.recordStages = this->RecordStages;
  p.weights.solver = p.contraction.solver;
  return p;
}

std::string vtkMedialContractionSkeleton::GetSolverNames() {
  return medial::joinNames(medial::sparseSolverNames());
}

void vtkMedialContractionSkeleton::SetSolver(const std::string& name) {
  medial::SparseSolverKind kind;
  if (!medial::parseSparseSolverKind(name, kind)) {
    vtkErrorMacro(<< "unknown solver '" << name << "' (" << GetSolverNames() << ")");
    return;
  }
  if (name != this->Solver) {
    this->Solver = name;
    this->Modified();
  }
}

std::vector<std::string> vtkMedialContractionSkeleton::GetStageNames() {
  return std::vector<std::string>(kStages, kStages + kStageCount);
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
  os << indent << "ReferenceVertices: " << this->ReferenceVertices << "\n";
  os << indent << "InitialContractionFactor: " << this->InitialContractionFactor << "\n";
  os << indent << "ContractionScale: " << this->ContractionScale << "\n";
  os << indent << "MaxContractionWeight: " << this->MaxContractionWeight << "\n";
  os << indent << "MaxAttractionWeight: " << this->MaxAttractionWeight << "\n";
  os << indent << "MaxIterations: " << this->MaxIterations << "\n";
  os << indent << "ShapeWeight: " << this->ShapeWeight << "\n";
  os << indent << "SamplingWeight: " << this->SamplingWeight << "\n";
  os << indent << "CollapseLengthFraction: " << this->CollapseLengthFraction << "\n";
  os << indent << "InitialAttractionWeight: " << this->InitialAttractionWeight << "\n";
  os << indent << "RefineEmbedding: " << this->RefineEmbedding << "\n";
  os << indent << "RestoreCycles: " << this->RestoreCycles << "\n";
  os << indent << "CenterNodes: " << this->CenterNodes << "\n";
  os << indent << "ComputeWeights: " << this->ComputeWeights << "\n";
  os << indent << "HeatConstant: " << this->HeatConstant << "\n";
  os << indent << "Solver: " << this->Solver << "\n";
  os << indent << "RecordStages: " << this->RecordStages << "\n";
}

vtkPolyData* vtkMedialContractionSkeleton::GetContractionStep(int step) const {
  return step >= 0 && step < this->GetNumberOfContractionSteps() ? this->Steps[size_t(step)].Get() : nullptr;
}

void vtkMedialContractionSkeleton::KeepStages(const medial::SkeletonByContractionResult& result) {
  const auto number = [](const char* name, double value) {
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name);
    array->InsertNextValue(value);
    return array;
  };
  for (size_t t = 0; t < result.contractionSteps.size(); ++t) {
    const medial::ContractionStep& step = result.contractionSteps[t];
    vtkSmartPointer<vtkPolyData> mesh = medial::polyDataFromMesh({step.positions, result.contractedFaces});
    mesh->GetPointData()->AddArray(medial::doubleArray("Laplacian", Eigen::MatrixXd(step.laplacian)));
    mesh->GetPointData()->AddArray(medial::doubleArray("AttractionWeight", Eigen::MatrixXd(step.attraction)));
    mesh->GetFieldData()->AddArray(number("ContractionWeight", step.contractionWeight));
    mesh->GetFieldData()->AddArray(number("Iteration", double(t)));
    mesh->GetFieldData()->AddArray(number("AreaRatio", step.areaRatio));
    mesh->GetFieldData()->AddArray(number("VolumeRatio", step.volumeRatio));
    if (t + 1 == result.contractionSteps.size())  // the mesh the surgery collapsed: in which order
      mesh->GetPointData()->AddArray(medial::intArray("CollapseOrder", result.collapseOrder));
    this->Steps.push_back(mesh);
  }
  this->SurgerySkeleton = medial::polyDataFromSkeleton(result.surgerySkeleton);
  this->UnselectedSkeleton = medial::polyDataFromSkeleton(result.unselectedSkeleton);
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
  const vtkSmartPointer<vtkPolyData> triangles = medial::triangulated(input);
  const medial::TriangleMesh mesh = medial::toTriangleMesh(triangles);

  const medial::SkeletonByContractionParameters p = this->MakeParameters();
  this->Steps.clear();
  this->SurgerySkeleton = this->UnselectedSkeleton = nullptr;
  const medial::SkeletonByContractionResult result =
      medial::skeletonByContraction(mesh, p, medial::progressOf(this));
  this->ContractionIterations = result.contractionIterations;
  this->CurveSkeletonNodes = result.curveSkeletonNodes;
  this->ContractedVertices = result.contractedVertices;
  this->Genus = result.cycleRepair.genus;
  this->RestoredCycles = result.cycleRepair.cyclesAdded;
  this->SelectionNote.clear();
  const double seconds[kStageCount] = {result.decimationSeconds,    result.contractionSeconds,
                                       result.factorizationSeconds, result.surgerySeconds,
                                       result.refinementSeconds,    result.selectionSeconds,
                                       result.radiiSeconds,         result.weightsSeconds};
  std::copy(seconds, seconds + kStageCount, this->Seconds);
  if (!result.ok()) {
    medial::reportError(this, result.error);
    return 0;
  }

  skeletonOutput->ShallowCopy(medial::polyDataFromSkeleton(result.skeleton));
  this->SelectionNote = result.selectionNote;
  if (!result.selectionNote.empty()) {
    auto note = vtkSmartPointer<vtkStringArray>::New();
    note->SetName("SelectionNote");
    note->InsertNextValue(result.selectionNote);
    skeletonOutput->GetFieldData()->AddArray(note);
    vtkWarningMacro(<< result.selectionNote);
  }
  if (this->RecordStages) this->KeepStages(result);
  meshOutput->ShallowCopy(triangles);
  meshOutput->GetPointData()->AddArray(medial::intArray("SkeletonNode", result.vertexToNode));
  // Where the contraction took each vertex (paper Fig. 5: the contracted mesh, before the surgery).
  auto contracted = vtkSmartPointer<vtkDoubleArray>::New();
  contracted->SetName("ContractedPosition");
  contracted->SetNumberOfComponents(3);
  contracted->SetNumberOfTuples(result.contracted.rows());
  for (Eigen::Index v = 0; v < result.contracted.rows(); ++v)
    for (int c = 0; c < 3; ++c) contracted->SetTypedComponent(v, c, result.contracted(v, c));
  meshOutput->GetPointData()->AddArray(contracted);
  if (this->ComputeWeights)
    meshOutput->GetPointData()->AddArray(medial::doubleArray("SkinWeights", result.weights));
  return 1;
}
