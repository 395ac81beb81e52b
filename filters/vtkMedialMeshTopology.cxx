#include "vtkMedialMeshTopology.h"

#include "mesh/MeshTopology.h"

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
}

namespace {

void addFaces(vtkCellArray* cells, bool strips, std::vector<std::vector<int64_t>>& faces) {
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (cells->InitTraversal(); cells->GetNextCell(ids);) {
    const vtkIdType n = ids->GetNumberOfIds();
    if (!strips) {
      faces.emplace_back(ids->begin(), ids->end());
      continue;
    }
    for (vtkIdType k = 0; k + 2 < n; ++k) {  // strip triangle k, with alternating orientation
      if (k % 2 == 0)
        faces.push_back({ids->GetId(k), ids->GetId(k + 1), ids->GetId(k + 2)});
      else
        faces.push_back({ids->GetId(k + 1), ids->GetId(k), ids->GetId(k + 2)});
    }
  }
}

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

  std::vector<std::vector<int64_t>> faces;
  faces.reserve(input->GetNumberOfPolys() + input->GetNumberOfStrips());
  addFaces(input->GetPolys(), false, faces);
  addFaces(input->GetStrips(), true, faces);
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
  this->UpdateProgress(1.0);
  return 1;
}
