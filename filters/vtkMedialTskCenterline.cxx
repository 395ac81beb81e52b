#include "vtkMedialTskCenterline.h"

#include "MedialProgress.h"
#include "MedialMeshData.h"
#include "MedialLumenSurface.h"
#include "MedialVolumeData.h"
#include "centerline/TskCenterline.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkUnsignedCharArray.h>

#include <functional>

vtkStandardNewMacro(vtkMedialTskCenterline);

namespace {

using medial::doubleArray;

// Port 0: one polyline per branch; a branch starts at its junction point on its parent (shared).
void writePolylines(const medial::TskCenterlineResult& result, bool branchArrays, vtkPolyData* output) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  std::vector<double> radius, arcLength;
  std::vector<int> branchId, parentId, bridged;
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  std::vector<vtkIdType> firstId(result.branches.size());
  for (size_t b = 0; b < result.branches.size(); ++b) {
    const medial::Centerline& centerline = result.branches[b];
    firstId[b] = points->GetNumberOfPoints();
    const bool joined = result.parent[b] >= 0;
    lines->InsertNextCell(vtkIdType(centerline.points.size()) + (joined ? 1 : 0));
    if (joined) lines->InsertCellPoint(firstId[size_t(result.parent[b])] + result.junction[b]);
    for (size_t k = 0; k < centerline.points.size(); ++k) {
      lines->InsertCellPoint(points->InsertNextPoint(centerline.points[k].data()));
      radius.push_back(centerline.radius[k]);
      arcLength.push_back(centerline.arcLength[k]);
      bridged.push_back(centerline.bridged.empty() ? 0 : centerline.bridged[k]);
    }
    branchId.push_back(int(b));
    parentId.push_back(result.parent[b]);
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(doubleArray("Radius", radius));
  output->GetPointData()->AddArray(doubleArray("ArcLength", arcLength));
  output->GetPointData()->AddArray(medial::intArray("Bridged", bridged));
  if (!branchArrays) return;
  output->GetCellData()->AddArray(medial::intArray("Branch", branchId));
  output->GetCellData()->AddArray(medial::intArray("ParentBranch", parentId));
}

// Port 1: the profile, one row per section. Port 2: the unfolded wall, angle along x and arc length
// along y.
void writeSections(const medial::TubeSections& sections, double spacing, vtkTable* table,
                   vtkImageData* terrain) {
  table->AddColumn(doubleArray("ArcLength", sections.arcLength));
  table->AddColumn(doubleArray("MinDiameter", sections.minDiameter));
  table->AddColumn(doubleArray("MaxDiameter", sections.maxDiameter));
  table->AddColumn(doubleArray("Perimeter", sections.perimeter));
  table->AddColumn(doubleArray("Area", sections.area));
  std::vector<int> bridged(sections.arcLength.size(), 0);
  for (size_t k = 0; k < sections.bridged.size() && k < bridged.size(); ++k) bridged[k] = sections.bridged[k];
  table->AddColumn(medial::intArray("Bridged", bridged));
  const int rays = sections.rays, count = int(sections.arcLength.size());
  terrain->SetDimensions(rays, count, 1);
  terrain->SetSpacing(360.0 / rays, spacing, 1.0);
  auto distance = vtkSmartPointer<vtkDoubleArray>::New();
  distance->SetName("WallDistance");
  distance->SetNumberOfValues(vtkIdType(rays) * count);
  for (int y = 0; y < count; ++y)
    for (int x = 0; x < rays; ++x)
      distance->SetValue(vtkIdType(y) * rays + x, sections.wall[size_t(y)][size_t(x)]);
  terrain->GetPointData()->SetScalars(distance);
  auto bridgedRows = vtkSmartPointer<vtkUnsignedCharArray>::New();  // 1 on the rows of bridged sections
  bridgedRows->SetName("Bridged");
  bridgedRows->SetNumberOfValues(vtkIdType(rays) * count);
  for (int y = 0; y < count; ++y)
    for (int x = 0; x < rays; ++x)
      bridgedRows->SetValue(vtkIdType(y) * rays + x,
                            size_t(y) < sections.bridged.size() ? sections.bridged[size_t(y)] : 0);
  terrain->GetPointData()->AddArray(bridgedRows);
}

}  // namespace

vtkMedialTskCenterline::vtkMedialTskCenterline() {
  this->SetNumberOfOutputPorts(4);
  const medial::TskCenterlineParameters defaults;
  this->Mode = Selection(int(defaults.selection));
  this->Label = int(defaults.label);
  this->ThresholdLow = defaults.thresholdLow;
  this->ThresholdHigh = defaults.thresholdHigh;
  this->BorderParts = int(defaults.borderParts);
  this->FillHoles = defaults.fillHoles;
  this->HasSeed = defaults.seed.has_value();
  this->MaxGap = defaults.maxGap;
  this->MinimumPartVolume = defaults.minimumPartVolume;
  this->AntecedentWidth = defaults.tsk.antecedentWidth;
  this->SampleSpacing = defaults.tsk.sampleSpacing;
  this->CenteringIterations = defaults.tsk.centeringIterations;
  this->DetectBranches = defaults.detectBranches;
  this->MinimumBranchLength = defaults.minimumBranchLength;
  this->ComputeSections = defaults.computeSections;
  this->SectionSpacing = defaults.sections.spacing;
  this->SectionRays = defaults.sections.rays;
  const medial::LumenSurfaceParameters surface;
  this->SurfaceTriangles = surface.maximumTriangles;
  this->SurfaceSmoothing = surface.smoothingIterations;
}

medial::TskCenterlineParameters vtkMedialTskCenterline::MakeParameters() const {
  static_assert(int(medial::VoxelSelection::Label) == int(Selection::Label) &&
                    int(medial::VoxelSelection::Automatic) == int(Selection::Automatic),
                "one order of selections");
  static_assert(int(medial::BorderParts::Keep) == BORDER_PARTS_KEEP, "one order of border rules");
  medial::TskCenterlineParameters p;
  p.selection = medial::VoxelSelection(int(this->Mode));
  p.label = this->Label;
  p.thresholdLow = this->ThresholdLow;
  p.thresholdHigh = this->ThresholdHigh;
  p.borderParts = medial::BorderParts(this->BorderParts);
  p.fillHoles = this->FillHoles;
  if (this->HasSeed) p.seed = Eigen::Vector3d(this->Seed[0], this->Seed[1], this->Seed[2]);
  p.maxGap = this->MaxGap;
  p.minimumPartVolume = this->MinimumPartVolume;
  p.tsk.antecedentWidth = this->AntecedentWidth;
  p.tsk.sampleSpacing = this->SampleSpacing;
  p.tsk.centeringIterations = this->CenteringIterations;
  p.detectBranches = this->DetectBranches;
  p.minimumBranchLength = this->MinimumBranchLength;
  p.computeSections = this->ComputeSections;
  p.recordStages = this->RecordStages;
  p.keepStructure = this->ComputeSurface;
  p.sections.spacing = this->SectionSpacing;
  p.sections.rays = this->SectionRays;
  return p;
}

void vtkMedialTskCenterline::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Selection: " << this->GetSelectionName() << "\n";
  os << indent << "Label: " << this->Label << "\n";
  os << indent << "Threshold: " << this->ThresholdLow << " " << this->ThresholdHigh << "\n";
  const char* border[] = {"automatic", "drop", "keep"};
  os << indent << "BorderParts: " << border[this->BorderParts] << "\n";
  os << indent << "FillHoles: " << this->FillHoles << "\n";
  os << indent << "Seed: ";
  if (this->HasSeed)
    os << this->Seed[0] << " " << this->Seed[1] << " " << this->Seed[2] << "\n";
  else
    os << "(the lowest end)\n";
  os << indent << "MaxGap: " << this->MaxGap << "\n";
  os << indent << "MinimumPartVolume: " << this->MinimumPartVolume << "\n";
  os << indent << "AntecedentWidth: " << this->AntecedentWidth << "\n";
  os << indent << "SampleSpacing: " << this->SampleSpacing << "\n";
  os << indent << "CenteringIterations: " << this->CenteringIterations << "\n";
  os << indent << "DetectBranches: " << this->DetectBranches << "\n";
  os << indent << "MinimumBranchLength: " << this->MinimumBranchLength << "\n";
  os << indent << "ComputeSections: " << this->ComputeSections << "\n";
  os << indent << "SectionSpacing: " << this->SectionSpacing << "\n";
  os << indent << "SectionRays: " << this->SectionRays << "\n";
  os << indent << "ComputeSurface: " << this->ComputeSurface << "\n";
  os << indent << "SurfaceTriangles: " << this->SurfaceTriangles << "\n";
  os << indent << "SurfaceSmoothing: " << this->SurfaceSmoothing << "\n";
}

void vtkMedialTskCenterline::SetLabel(int label) {
  this->Mode = Selection::Label;
  this->Label = label;
  this->Modified();
}

void vtkMedialTskCenterline::SetThreshold(double low, double high) {
  this->Mode = Selection::Threshold;
  this->ThresholdLow = low;
  this->ThresholdHigh = high;
  this->Modified();
}

const char* vtkMedialTskCenterline::GetSelectionName() const {
  return this->Mode == Selection::Label       ? "label"
         : this->Mode == Selection::Threshold ? "threshold"
         : this->Mode == Selection::Automatic ? "automatic"
                                              : "non-zero";
}

void vtkMedialTskCenterline::SelectNonZero() {
  this->Mode = Selection::NonZero;
  this->Modified();
}

void vtkMedialTskCenterline::SelectAutomatically() {
  this->Mode = Selection::Automatic;
  this->Modified();
}

bool vtkMedialTskCenterline::GetDropBorderParts() const {
  if (this->BorderParts == BORDER_PARTS_AUTOMATIC) return this->Mode == Selection::Threshold;
  return this->BorderParts == BORDER_PARTS_DROP;
}

void vtkMedialTskCenterline::SetSeed(double x, double y, double z) {
  this->HasSeed = true;
  this->Seed[0] = x;
  this->Seed[1] = y;
  this->Seed[2] = z;
  this->Modified();
}

void vtkMedialTskCenterline::ClearSeed() {
  this->HasSeed = false;
  this->Modified();
}

int vtkMedialTskCenterline::FillOutputPortInformation(int port, vtkInformation* info) {
  if (port == 0) return this->Superclass::FillOutputPortInformation(port, info);
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1   ? "vtkTable"
                                             : port == 2 ? "vtkImageData"
                                                         : "vtkPolyData");
  return 1;
}

int vtkMedialTskCenterline::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

std::vector<std::string> vtkMedialTskCenterline::GetStageNames() {
  return {"selection", "cleanup", "axis", "sections"};
}

double vtkMedialTskCenterline::GetBridgedGap(int i) const {
  return i >= 0 && i < this->GetNumberOfBridgedGaps() ? this->BridgedGaps[size_t(i)] : 0.0;
}

const char* vtkMedialTskCenterline::GetNote(int i) const {
  return i >= 0 && i < this->GetNumberOfNotes() ? this->Notes[size_t(i)].c_str() : "";
}

double vtkMedialTskCenterline::GetStageSeconds(const std::string& stage) const {
  for (const auto& [name, seconds] : this->StageSeconds)
    if (name == stage) return seconds;
  return 0;
}

int vtkMedialTskCenterline::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                        vtkInformationVector* outputVector) {
  medial::ScalarVolume volume;
  std::string error;
  if (!medial::scalarVolumeOf(vtkImageData::GetData(inputVector[0]), volume, error)) {
    vtkErrorMacro(<< error);
    return 0;
  }
  const medial::TskCenterlineParameters p = this->MakeParameters();
  this->Stages.clear();
  this->StageLabels = nullptr;
  // With the surface, the centerline's share of the progress bar is 85 % (the surface takes about as long).
  const std::function<bool(double)> progress = medial::progressOf(this);
  const double share = p.keepStructure ? 0.85 : 1.0;
  medial::TskCenterlineResult result =
      medial::tskCenterline(volume, p, [&](double f) { return progress(share * f); });
  this->StructureVoxels = result.structureVoxels;
  this->PrimitiveCenterlinePoints = result.primitiveCenterlinePoints;
  this->StageSeconds = result.stageSeconds;
  this->PartsFollowed = result.partsFollowed;
  this->BridgedGaps = result.bridgedGaps;
  this->Notes = result.notes;
  if (!result.ok()) {
    medial::reportError(this, result.error);
    return 0;
  }
  if (p.keepStructure) {
    medial::LumenSurfaceParameters surface;
    surface.maximumTriangles = this->SurfaceTriangles;
    surface.smoothingIterations = this->SurfaceSmoothing;
    const vtkSmartPointer<vtkPolyData> lumen = medial::lumenSurface(
        result.structure, surface, [&](double f) { return progress(share + (1 - share) * f); });
    result.structure = {};  // the mask's memory back before the caller goes on
    if (lumen->GetNumberOfPolys() == 0) {
      medial::reportError(this, this->GetAbortExecute() ? medial::Error::cancelled()
                                                        : medial::Error("the lumen has no surface"));
      return 0;
    }
    vtkPolyData::GetData(outputVector, 3)->ShallowCopy(lumen);  // the other ports only once it is there
  }
  writePolylines(result, p.detectBranches, vtkPolyData::GetData(outputVector, 0));
  if (p.computeSections)
    writeSections(result.sections, p.sections.spacing, vtkTable::GetData(outputVector, 1),
                  vtkImageData::GetData(outputVector, 2));
  if (p.recordStages && !result.stages.voxels.empty()) this->KeepStages(result.stages);
  return 1;
}

vtkImageData* vtkMedialTskCenterline::GetStageLabels() const { return this->StageLabels; }

vtkPolyData* vtkMedialTskCenterline::GetStageData(const std::string& name) const {
  const auto found = this->Stages.find(name);
  return found != this->Stages.end() ? found->second.Get() : nullptr;
}

namespace {

// Points as a polydata: one polyline through them (line) or one vertex cell each.
vtkSmartPointer<vtkPolyData> pointSet(const std::vector<Eigen::Vector3d>& at, bool line) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  if (line) cells->InsertNextCell(vtkIdType(at.size()));
  for (const Eigen::Vector3d& p : at) {
    const vtkIdType id = points->InsertNextPoint(p.data());
    if (line)
      cells->InsertCellPoint(id);
    else
      cells->InsertNextCell(1, &id);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  if (line)
    data->SetLines(cells);
  else
    data->SetVerts(cells);
  return data;
}

}  // namespace

void vtkMedialTskCenterline::KeepStages(const medial::TskStages& stages) {
  vtkSmartPointer<vtkPolyData> voxels = pointSet(stages.voxels, false);
  voxels->GetPointData()->AddArray(medial::intArray("Layer", stages.layer));
  voxels->GetPointData()->AddArray(medial::intArray("Cluster", stages.cluster));
  std::vector<double> t(stages.voxels.size());
  for (size_t k = 0; k < t.size(); ++k) t[k] = t.size() > 1 ? double(k) / double(t.size() - 1) : 0.0;
  voxels->GetPointData()->AddArray(medial::doubleArray("T", t));
  this->Stages["voxels"] = voxels;
  vtkSmartPointer<vtkPolyData> primitive = pointSet(stages.primitive, true);
  primitive->GetPointData()->AddArray(medial::intArray("Layer", stages.primitiveLayer));
  primitive->GetPointData()->AddArray(medial::doubleArray(
      "BorderDistance",
      std::vector<double>(stages.primitiveBorderDistance.begin(), stages.primitiveBorderDistance.end())));
  this->Stages["primitive"] = primitive;
  vtkSmartPointer<vtkPolyData> model = pointSet(stages.model.point, true);
  model->GetPointData()->AddArray(medial::doubleArray("T", stages.model.t));
  this->Stages["tsk-model"] = model;
  auto labels = vtkSmartPointer<vtkImageData>::New();
  labels->SetDimensions(stages.boxSize.data());
  labels->SetOrigin(stages.boxOrigin.data());
  labels->SetSpacing(stages.boxSpacing.data());
  double direction[9];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) direction[3 * r + c] = stages.boxDirection(r, c);
  labels->SetDirectionMatrix(direction);
  labels->GetPointData()->SetScalars(medial::intArray("Layer", stages.layerVolume));
  labels->GetPointData()->AddArray(medial::intArray("Cluster", stages.clusterVolume));
  this->StageLabels = labels;
}
