#include "vtkMedialSketchSkeleton.h"

#include "MedialSkeletonData.h"
#include "sketch/SketchSkeleton.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

vtkStandardNewMacro(vtkMedialSketchSkeleton);

vtkMedialSketchSkeleton::vtkMedialSketchSkeleton() { this->SetNumberOfOutputPorts(2); }

void vtkMedialSketchSkeleton::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SimplificationThreshold: " << this->SimplificationThreshold << "\n";
  os << indent << "MergingThreshold: " << this->MergingThreshold << "\n";
  os << indent << "PruningThreshold: " << this->PruningThreshold << "\n";
  os << indent << "CollapsingThreshold: " << this->CollapsingThreshold << "\n";
  os << indent << "PartThresholds: " << this->PartThresholds.size() << " parts\n";
  os << indent << "BranchThresholds: " << this->BranchThresholds.size() << " branches\n";
  os << indent << "UnitLength: " << this->UnitLength << "\n";
  os << indent << "ResampleStep: " << this->ResampleStep << "\n";
  os << indent << "PolygonTolerance: " << this->PolygonTolerance << "\n";
  os << indent << "ShapeWeight: " << this->ShapeWeight << "\n";
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "MeshEdgeLength: " << this->MeshEdgeLength << "\n";
  os << indent << "Inflate: " << this->Inflate << "\n";
}

void vtkMedialSketchSkeleton::SetPartThresholds(int part, double simplification, double merging, double pruning,
                                                double collapsing) {
  this->PartThresholds[part] = {simplification, merging, pruning, collapsing};
  this->Modified();
}

void vtkMedialSketchSkeleton::SetBranchSimplification(int part, int branch, double simplification) {
  this->BranchThresholds[{part, branch}] = simplification;
  this->Modified();
}

void vtkMedialSketchSkeleton::ClearLocalThresholds() {
  this->PartThresholds.clear();
  this->BranchThresholds.clear();
  this->Modified();
}

namespace {

vtkSmartPointer<vtkIntArray> intArray(const char* name, const std::vector<int>& values) {
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(vtkIdType(values.size()));
  for (size_t i = 0; i < values.size(); ++i) array->SetValue(vtkIdType(i), values[i]);
  return array;
}

// The strokes of the input's line cells, with their placements.
bool readStrokes(vtkPolyData* input, std::vector<medial::SketchPart>& parts, std::string& error) {
  vtkCellArray* lines = input ? input->GetLines() : nullptr;
  if (!lines || lines->GetNumberOfCells() == 0) {
    error = "no stroke: the input needs closed polylines (line cells)";
    return false;
  }
  vtkDataArray* placement = input->GetCellData()->GetArray("Placement");
  if (placement && placement->GetNumberOfComponents() != 16) {
    error = "the Placement cell array must have 16 components (a row-major 4x4 matrix)";
    return false;
  }
  const vtkIdType firstLine = input->GetNumberOfVerts();  // cell ids: verts, then lines
  auto cell = vtkSmartPointer<vtkIdList>::New();
  lines->InitTraversal();
  for (vtkIdType c = 0; lines->GetNextCell(cell); ++c) {
    medial::SketchPart part;
    for (vtkIdType k = 0; k < cell->GetNumberOfIds(); ++k) {
      double p[3];
      input->GetPoint(cell->GetId(k), p);
      part.stroke.emplace_back(p[0], p[1]);
    }
    if (placement) {
      double m[16];
      placement->GetTuple(firstLine + c, m);
      for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k) part.placement(r, k) = m[4 * r + k];
    }
    parts.push_back(std::move(part));
  }
  return true;
}

}  // namespace

int vtkMedialSketchSkeleton::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                         vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* skeletonOutput = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* meshOutput = vtkPolyData::GetData(outputVector, 1);
  std::vector<medial::SketchPart> parts;
  std::string error;
  if (!readStrokes(input, parts, error)) {
    vtkErrorMacro(<< error);
    return 0;
  }
  for (const auto& [part, t] : this->PartThresholds)
    if (part >= 0 && part < int(parts.size())) parts[part].thresholds = medial::RefinementThresholds{t[0], t[1], t[2], t[3]};
  for (const auto& [key, value] : this->BranchThresholds)
    if (key.first >= 0 && key.first < int(parts.size())) parts[key.first].branchSimplification[key.second] = value;
  medial::SketchParameters p;
  p.thresholds = {this->SimplificationThreshold, this->MergingThreshold, this->PruningThreshold, this->CollapsingThreshold};
  p.unitLength = this->UnitLength;
  p.resampleStep = this->ResampleStep;
  p.polygonTolerance = this->PolygonTolerance;
  p.shapeWeight = this->ShapeWeight;
  p.thickness = this->Thickness;
  p.meshEdgeLength = this->MeshEdgeLength;
  p.inflate = this->Inflate;
  const medial::SketchResult result = medial::sketchSkeleton(parts, p, [this](double f) {
    this->UpdateProgress(f);
    return !this->GetAbortExecute();
  });
  if (!result.ok()) {
    vtkErrorMacro(<< result.error);
    return 0;
  }
  const medial::SketchGraph& graph = result.graph;
  skeletonOutput->ShallowCopy(medial::polyDataFromSkeleton(graph.skeleton));
  skeletonOutput->GetPointData()->AddArray(intArray("Part", graph.nodePart));
  skeletonOutput->GetCellData()->AddArray(intArray("Part", graph.edgePart));
  skeletonOutput->GetCellData()->AddArray(intArray("Branch", graph.edgeBranch));

  if (this->Inflate) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    for (int v = 0; v < result.mesh.vertices.rows(); ++v)
      points->InsertNextPoint(result.mesh.vertices(v, 0), result.mesh.vertices(v, 1), result.mesh.vertices(v, 2));
    auto triangles = vtkSmartPointer<vtkCellArray>::New();
    for (int f = 0; f < result.mesh.faces.rows(); ++f) {
      const vtkIdType ids[3] = {result.mesh.faces(f, 0), result.mesh.faces(f, 1), result.mesh.faces(f, 2)};
      triangles->InsertNextCell(3, ids);
    }
    meshOutput->SetPoints(points);
    meshOutput->SetPolys(triangles);
    meshOutput->GetPointData()->AddArray(intArray("Part", result.meshVertexPart));
  }
  return 1;
}
