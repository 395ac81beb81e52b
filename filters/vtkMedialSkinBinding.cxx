#include "vtkMedialSkinBinding.h"

#include "MedialProgress.h"
#include "MedialMeshData.h"
#include "MedialSkeletonData.h"
#include "rig/SkinBinding.h"

#include <vtkAlgorithmOutput.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkMedialSkinBinding);

vtkMedialSkinBinding::vtkMedialSkinBinding() {
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  this->HeatConstant = medial::HeatWeightParameters{}.heatConstant;
}

void vtkMedialSkinBinding::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HeatConstant: " << this->HeatConstant << "\n";
  os << indent << "Root: " << this->Root << "\n";
}

void vtkMedialSkinBinding::SetSkeletonData(vtkPolyData* skeleton) { this->SetInputData(1, skeleton); }

void vtkMedialSkinBinding::SetSkeletonConnection(vtkAlgorithmOutput* output) {
  this->SetInputConnection(1, output);
}

int vtkMedialSkinBinding::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialSkinBinding::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                      vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* skeletonInput = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* meshOutput = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* skeletonOutput = vtkPolyData::GetData(outputVector, 1);
  this->ChosenRoot = -1;
  this->NodesOutside = this->InvisibleVertices = 0;
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0) {
    vtkErrorMacro(<< "the mesh (port 0) has no polygons: a surface mesh is needed");
    return 0;
  }
  medial::Skeleton skeleton;
  std::string error;
  if (!skeletonInput) {
    vtkErrorMacro(<< "no skeleton on port 1");
    return 0;
  }
  if (!medial::skeletonFromPolyData(skeletonInput, skeleton, error)) {
    vtkErrorMacro(<< "the skeleton: " << error);
    return 0;
  }
  const auto problems = medial::validateSkeleton(skeleton);
  if (!problems.empty()) {
    vtkErrorMacro(<< "the skeleton: " << medial::describeProblems(problems));
    return 0;
  }
  if (this->Root >= skeleton.nodeCount()) {
    vtkErrorMacro(<< "Root " << this->Root << " is not a node of the skeleton (" << skeleton.nodeCount()
                  << " nodes)");
    return 0;
  }
  if (this->Root >= 0) skeleton.root = this->Root;

  const medial::TriangleMesh mesh = medial::toTriangleMesh(medial::triangulated(input));
  medial::HeatWeightParameters parameters;
  parameters.heatConstant = this->HeatConstant;
  const medial::SkinBindingResult result =
      medial::bindSkin(mesh, skeleton, parameters, medial::progressOf(this));
  if (!result.ok()) {
    medial::reportError(this, result.error);
    return 0;
  }
  this->ChosenRoot = result.root;
  this->NodesOutside = result.nodesOutside;
  this->InvisibleVertices = result.invisibleVertices;
  if (result.nodesOutside > 0)
    vtkWarningMacro(<< result.nodesOutside << " of " << skeleton.nodeCount()
                    << " skeleton nodes lie outside the mesh; their bones are weighted by diffusion");

  meshOutput->ShallowCopy(input);
  meshOutput->GetPointData()->AddArray(medial::doubleArray("SkinWeights", result.weights));
  std::vector<int> strongest(size_t(result.weights.rows()));
  for (Eigen::Index v = 0; v < result.weights.rows(); ++v)
    result.weights.row(v).maxCoeff(&strongest[size_t(v)]);
  meshOutput->GetPointData()->AddArray(medial::intArray("Bone", strongest));
  skeleton.root = result.root;
  skeletonOutput->ShallowCopy(medial::polyDataFromSkeleton(skeleton));
  return 1;
}
