#include "vtkMedialSQM.h"

#include "MedialSkeletonData.h"
#include "sqm/SqmMesher.h"

#include <vtkCellArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

vtkStandardNewMacro(vtkMedialSQM);

void vtkMedialSQM::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Smoothing: " << this->Smoothing << "\n";
  os << indent << "Pairing: " << this->Pairing << "\n";
  os << indent << "LinearRingVertices: " << this->LinearRingVertices << "\n";
  os << indent << "Capsules: " << this->Capsules << "\n";
  os << indent << "PairTriangles: " << this->PairTriangles << "\n";
  os << indent << "SubdivisionLevels: " << this->SubdivisionLevels << "\n";
  os << indent << "SharpScaling: " << this->SharpScaling << " (minimum " << this->SharpMinimumScale << ")\n";
  os << indent << "FoldRepair: " << this->FoldRepair << "\n";
}

void vtkMedialSQM::SetSmoothing(const std::string& name) {
  medial::LieSmoothing smoothing;
  if (!medial::parseLieSmoothing(name, smoothing)) {
    vtkErrorMacro(<< "unknown smoothing '" << name << "' (quaternion, averaging, area-laplacian, valency-laplacian)");
    return;
  }
  if (name != this->Smoothing) {
    this->Smoothing = name;
    this->Modified();
  }
}

void vtkMedialSQM::SetPairing(const std::string& name) {
  medial::RingPairing pairing;
  if (!medial::parseRingPairing(name, pairing)) {
    vtkErrorMacro(<< "unknown pairing '" << name << "' (total-distance, distance, angle)");
    return;
  }
  if (name != this->Pairing) {
    this->Pairing = name;
    this->Modified();
  }
}

int vtkMedialSQM::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  medial::Skeleton skeleton;
  std::string error;
  if (!input || !medial::skeletonFromPolyData(input, skeleton, error)) {
    vtkErrorMacro(<< (input ? error : std::string("no input skeleton")));
    return 0;
  }
  this->MergedNodes = 0;
  this->FoldRepairedVertices = 0;
  medial::SqmParameters p;
  medial::parseLieSmoothing(this->Smoothing, p.smoothing);
  medial::parseRingPairing(this->Pairing, p.pairing);
  p.linearRingVertices = this->LinearRingVertices;
  p.capsules = this->Capsules;
  p.pairTriangles = this->PairTriangles;
  p.subdivisionLevels = this->SubdivisionLevels;
  p.sharpScaling.enabled = this->SharpScaling;
  p.foldRepair = this->FoldRepair;
  p.sharpScaling.minimumScale = this->SharpMinimumScale;
  const medial::SqmResult result = medial::sqmMesh(skeleton, p, [this](double f) {
    this->UpdateProgress(f);
    return !this->GetAbortExecute();
  });
  if (!result.ok()) {
    vtkErrorMacro(<< result.error);
    return 0;
  }
  this->MergedNodes = result.mergedNodes;
  this->FoldRepairedVertices = result.foldRepairedVertices;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (const auto& v : result.mesh.vertices) points->InsertNextPoint(v.x(), v.y(), v.z());
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& face : result.mesh.faces) {
    polys->InsertNextCell(vtkIdType(face.size()));
    for (int v : face) polys->InsertCellPoint(v);
  }
  auto nodes = vtkSmartPointer<vtkIntArray>::New();
  nodes->SetName("SkeletonNode");
  for (int node : result.mesh.vertexNode) nodes->InsertNextValue(node);
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->AddArray(nodes);
  return 1;
}
