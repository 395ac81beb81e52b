#include "vtkMedialSkeletonValidator.h"

#include "MedialSkeletonData.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

vtkStandardNewMacro(vtkMedialSkeletonValidator);

void vtkMedialSkeletonValidator::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RequireRadius: " << this->RequireRadius << "\n";
  os << indent << "ProblemCount: " << this->ProblemCount << "\n";
}

int vtkMedialSkeletonValidator::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                            vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->ProblemCount = 0;

  medial::Skeleton skeleton;
  std::string error;
  if (!medial::skeletonFromPolyData(input, skeleton, error)) {
    this->ProblemCount = 1;
    vtkErrorMacro(<< "not a skeleton: " << error);
    return 0;
  }
  if (skeleton.nodes.empty()) {
    this->ProblemCount = 1;
    vtkErrorMacro(<< "the skeleton is empty (no nodes)");
    return 0;
  }
  if (this->RequireRadius && skeleton.radii.empty()) {
    this->ProblemCount = 1;
    vtkErrorMacro(<< "the skeleton has no " << medial::kRadiusArray << " point array");
    return 0;
  }
  const auto problems = medial::validateSkeleton(skeleton, 1000);
  this->ProblemCount = static_cast<int>(problems.size());
  if (!problems.empty()) {
    vtkErrorMacro(<< "invalid skeleton: " << medial::describeProblems(problems));
    return 0;
  }

  output->ShallowCopy(input);
  auto nodeType = vtkSmartPointer<vtkUnsignedCharArray>::New();
  nodeType->SetName(medial::kNodeTypeArray);
  const auto types = medial::classifyNodes(skeleton);
  nodeType->SetNumberOfValues(static_cast<vtkIdType>(types.size()));
  for (size_t i = 0; i < types.size(); ++i) nodeType->SetValue(i, static_cast<unsigned char>(types[i]));
  output->GetPointData()->AddArray(nodeType);
  return 1;
}
