#include "vtkMedialMeshTopology.h"

#include "MedialMeshData.h"
#include "mesh/MeshTopology.h"
#include "mesh/SelfIntersections.h"

#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkMedialMeshTopology);

void vtkMedialMeshTopology::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfFaces: " << this->NumberOfFaces << "\n";
  os << indent << "NumberOfEdges: " << this->NumberOfEdges << "\n";
  os << indent << "NumberOfBorderEdges: " << this->NumberOfBorderEdges << "\n";
  os << indent << "NumberOfNonManifoldEdges: " << this->NumberOfNonManifoldEdges << "\n";
  os << indent << "NumberOfComponents: " << this->NumberOfComponents << "\n";
  os << indent << "NumberOfBoundaryLoops: " << this->NumberOfBoundaryLoops << "\n";
  os << indent << "EulerCharacteristic: " << this->EulerCharacteristic << "\n";
  os << indent << "Genus: " << this->Genus << "\n";
  os << indent << "ClosedManifold: " << this->ClosedManifold << "\n";
  os << indent << "CountSelfIntersections: " << this->CountSelfIntersections << "\n";
  os << indent << "NumberOfIntersectingFacePairs: " << this->NumberOfIntersectingFacePairs << "\n";
}

namespace {

void addCount(vtkFieldData* fieldData, const char* name, vtkIdType value) {
  auto array = vtkSmartPointer<vtkIdTypeArray>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}

}  // namespace

int vtkMedialMeshTopology::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                       vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);

  const std::vector<std::vector<int64_t>> faces = medial::polygonsOf(input);
  this->UpdateProgress(0.3);
  const medial::MeshTopology t = medial::computeMeshTopology(input->GetNumberOfPoints(), faces);

  this->NumberOfFaces = t.faces;
  this->NumberOfEdges = t.edges;
  this->NumberOfBorderEdges = t.borderEdges;
  this->NumberOfNonManifoldEdges = t.nonManifoldEdges;
  this->NumberOfComponents = t.components;
  this->NumberOfBoundaryLoops = t.boundaryLoops;
  this->EulerCharacteristic = t.eulerCharacteristic;
  this->Genus = t.genus;
  this->ClosedManifold = t.isClosedManifold();
  this->NumberOfIntersectingFacePairs = -1;
  if (this->CountSelfIntersections) {
    this->UpdateProgress(0.4);
    this->NumberOfIntersectingFacePairs =
        vtkIdType(medial::selfIntersectingFaces(medial::pointsOf(input), faces).size());
  }

  output->ShallowCopy(input);
  // A field data of our own: the shallow copy may share the input's, which must not change.
  auto fieldData = vtkSmartPointer<vtkFieldData>::New();
  fieldData->ShallowCopy(input->GetFieldData());
  output->SetFieldData(fieldData);
  addCount(fieldData, "Genus", t.genus);
  addCount(fieldData, "EulerCharacteristic", t.eulerCharacteristic);
  addCount(fieldData, "Components", t.components);
  addCount(fieldData, "BorderEdges", t.borderEdges);
  addCount(fieldData, "NonManifoldEdges", t.nonManifoldEdges);
  addCount(fieldData, "BoundaryLoops", t.boundaryLoops);
  if (this->CountSelfIntersections)
    addCount(fieldData, "IntersectingFacePairs", this->NumberOfIntersectingFacePairs);
  this->UpdateProgress(1.0);
  return 1;
}
