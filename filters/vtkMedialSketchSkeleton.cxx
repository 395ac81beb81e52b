#include "vtkMedialSketchSkeleton.h"

#include "MedialProgress.h"
#include "MedialMeshData.h"
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

vtkMedialSketchSkeleton::vtkMedialSketchSkeleton() {
  this->SetNumberOfOutputPorts(2);
  const medial::SketchParameters defaults;
  this->SimplificationThreshold = defaults.thresholds.simplification;
  this->MergingThreshold = defaults.thresholds.merging;
  this->PruningThreshold = defaults.thresholds.pruning;
  this->CollapsingThreshold = defaults.thresholds.collapsing;
  this->UnitLength = defaults.unitLength;
  this->ResampleStep = defaults.resampleStep;
  this->PolygonTolerance = defaults.polygonTolerance;
  this->ShapeWeight = defaults.shapeWeight;
  this->Thickness = defaults.thickness;
  this->MeshEdgeLength = defaults.meshEdgeLength;
  this->Inflate = defaults.inflate;
  this->MergeParts = defaults.mergeParts;
}

medial::SketchParameters vtkMedialSketchSkeleton::MakeParameters() const {
  medial::SketchParameters p;
  p.thresholds = {this->SimplificationThreshold, this->MergingThreshold, this->PruningThreshold,
                  this->CollapsingThreshold};
  p.unitLength = this->UnitLength;
  p.resampleStep = this->ResampleStep;
  p.polygonTolerance = this->PolygonTolerance;
  p.shapeWeight = this->ShapeWeight;
  p.thickness = this->Thickness;
  p.meshEdgeLength = this->MeshEdgeLength;
  p.inflate = this->Inflate;
  p.mergeParts = this->MergeParts;
  p.recordStages = this->RecordStages;
  return p;
}

void vtkMedialSketchSkeleton::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SimplificationThreshold: " << this->SimplificationThreshold << "\n";
  os << indent << "MergingThreshold: " << this->MergingThreshold << "\n";
  os << indent << "PruningThreshold: " << this->PruningThreshold << "\n";
  os << indent << "CollapsingThreshold: " << this->CollapsingThreshold << "\n";
  for (const auto& [part, t] : this->PartThresholds)
    os << indent << "PartThresholds[" << part << "]: " << t[0] << " " << t[1] << " " << t[2] << " " << t[3]
       << "\n";
  for (const auto& [key, value] : this->BranchThresholds)
    os << indent << "BranchSimplification[" << key.first << ", " << key.second << "]: " << value << "\n";
  os << indent << "UnitLength: " << this->UnitLength << "\n";
  os << indent << "ResampleStep: " << this->ResampleStep << "\n";
  os << indent << "PolygonTolerance: " << this->PolygonTolerance << "\n";
  os << indent << "ShapeWeight: " << this->ShapeWeight << "\n";
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "MeshEdgeLength: " << this->MeshEdgeLength << "\n";
  os << indent << "Inflate: " << this->Inflate << "\n";
  os << indent << "MergeParts: " << this->MergeParts << "\n";
  os << indent << "RecordStages: " << this->RecordStages << "\n";
}

void vtkMedialSketchSkeleton::SetPartThresholds(int part, double simplification, double merging,
                                                double pruning, double collapsing) {
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

// A sketch graph as a skeleton polydata with its labels: point data Part, cell data Part and Branch.
vtkSmartPointer<vtkPolyData> polyDataFromGraph(const medial::SketchGraph& graph) {
  vtkSmartPointer<vtkPolyData> data = medial::polyDataFromSkeleton(graph.skeleton);
  data->GetPointData()->AddArray(medial::intArray("Part", graph.nodePart));
  data->GetCellData()->AddArray(medial::intArray("Part", graph.edgePart));
  data->GetCellData()->AddArray(medial::intArray("Branch", graph.edgeBranch));
  return data;
}

}  // namespace

vtkPolyData* vtkMedialSketchSkeleton::GetStageSkeleton(const std::string& name) const {
  const auto found = this->Stages.find(name);
  return found != this->Stages.end() ? found->second.Get() : nullptr;
}

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
    if (part >= 0 && part < int(parts.size()))
      parts[part].thresholds = medial::RefinementThresholds{t[0], t[1], t[2], t[3]};
  for (const auto& [key, value] : this->BranchThresholds)
    if (key.first >= 0 && key.first < int(parts.size()))
      parts[key.first].branchSimplification[key.second] = value;
  const medial::SketchResult result =
      medial::sketchSkeleton(parts, this->MakeParameters(), medial::progressOf(this));
  if (!result.ok()) {
    medial::reportError(this, result.error);
    return 0;
  }
  skeletonOutput->ShallowCopy(polyDataFromGraph(result.graph));
  this->Stages.clear();
  for (const auto& [name, graph] : result.stages) this->Stages[name] = polyDataFromGraph(graph);
  if (this->Inflate) {
    const vtkSmartPointer<vtkPolyData> mesh = medial::polyDataFromMesh(result.mesh);
    meshOutput->SetPoints(mesh->GetPoints());  // the input's field data, passed on by the pipeline, stays
    meshOutput->SetPolys(mesh->GetPolys());
    meshOutput->GetPointData()->AddArray(medial::intArray("Part", result.meshVertexPart));
  }
  return 1;
}
