#include "vtkMedialTskCenterline.h"

#include "centerline/Branches.h"
#include "centerline/TskAxis.h"
#include "centerline/TubeSections.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMatrix3x3.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyLine.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkMedialTskCenterline);

void vtkMedialTskCenterline::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Selection: "
     << (this->Mode == Selection::Label ? "label " + std::to_string(this->Label)
         : this->Mode == Selection::Threshold
             ? "threshold " + std::to_string(this->ThresholdLow) + ".." + std::to_string(this->ThresholdHigh)
             : std::string("non-zero"))
     << "\n";
  os << indent << "DropBorderParts: " << this->DropBorderParts << "\n";
  os << indent << "FillHoles: " << this->FillHoles << "\n";
  os << indent << "AntecedentWidth: " << this->AntecedentWidth << "\n";
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
  this->DropBorderParts = true;
  this->Modified();
}

void vtkMedialTskCenterline::SelectNonZero() {
  this->Mode = Selection::NonZero;
  this->Modified();
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

vtkMedialTskCenterline::vtkMedialTskCenterline() { this->SetNumberOfOutputPorts(3); }

int vtkMedialTskCenterline::FillOutputPortInformation(int port, vtkInformation* info) {
  if (port == 0) return this->Superclass::FillOutputPortInformation(port, info);
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkTable" : "vtkImageData");
  return 1;
}

int vtkMedialTskCenterline::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

int vtkMedialTskCenterline::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                        vtkInformationVector* outputVector) {
  vtkImageData* image = vtkImageData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  int dims[3] = {0, 0, 0};
  if (image) image->GetDimensions(dims);
  if (!scalars || dims[0] < 2 || dims[1] < 2 || dims[2] < 2) {
    vtkErrorMacro(<< "a 3-D volume is needed (got " << dims[0] << " x " << dims[1] << " x " << dims[2] << " voxels)");
    return 0;
  }

  // The structure, on plain arrays.
  medial::BinaryVolume volume;
  volume.size = {dims[0], dims[1], dims[2]};
  double value[3];
  image->GetOrigin(value);
  volume.origin = Eigen::Vector3d(value[0], value[1], value[2]);
  image->GetSpacing(value);
  volume.spacing = Eigen::Vector3d(value[0], value[1], value[2]);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) volume.direction(r, c) = image->GetDirectionMatrix()->GetElement(r, c);
  volume.inside.resize(size_t(volume.voxelCount()));
  bool labelSeen = false;
  for (vtkIdType i = 0; i < volume.voxelCount(); ++i) {
    const double v = scalars->GetComponent(i, 0);
    bool in = v != 0;
    if (this->Mode == Selection::Label) in = v == this->Label;
    if (this->Mode == Selection::Threshold) in = v >= this->ThresholdLow && v <= this->ThresholdHigh;
    labelSeen |= in;
    volume.inside[size_t(i)] = in;
  }
  if (this->Mode == Selection::Label && !labelSeen) {
    vtkErrorMacro(<< "no voxel has the label " << this->Label);
    return 0;
  }
  if (this->DropBorderParts) medial::dropBorderTouchingParts(volume);
  medial::keepLargestComponent(volume);
  if (this->FillHoles) medial::fillHoles(volume);
  this->StructureVoxels = vtkIdType(std::count(volume.inside.begin(), volume.inside.end(), 1));
  if (this->StructureVoxels < 8) {
    vtkErrorMacro(<< "nothing is left to follow: " << this->StructureVoxels
                  << " voxels after selection and clean-up (check the label or threshold"
                  << (this->DropBorderParts ? "; parts touching the volume's border were dropped" : "") << ")");
    return 0;
  }
  medial::cropToStructure(volume, 1);  // every later step works on the structure's box only
  this->UpdateProgress(0.1);

  int64_t seed = -1;
  if (this->HasSeed) {
    const Eigen::Vector3d index = volume.continuousIndex(Eigen::Vector3d(this->Seed[0], this->Seed[1], this->Seed[2]));
    const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
    if (!volume.contains(i, j, k) || !volume.inside[size_t(volume.index(i, j, k))]) {
      vtkErrorMacro(<< "the seed (" << this->Seed[0] << ", " << this->Seed[1] << ", " << this->Seed[2]
                    << ") mm lies outside the structure");
      return 0;
    }
    seed = volume.index(i, j, k);
  }
  medial::TskParameters p;
  p.antecedentWidth = this->AntecedentWidth;
  p.sampleSpacing = this->SampleSpacing;
  p.centeringIterations = this->CenteringIterations;
  std::vector<medial::Centerline> branches;
  std::vector<int> parents;
  if (!(this->DetectBranches ? this->FollowBranches(volume, seed, p, branches, parents)
                             : this->FollowTube(volume, seed, p, branches, parents)))
    return 0;

  // One polyline per branch; a branch starts at the point of its parent nearest to its own first point
  // (the junction, shared).
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto radius = vtkSmartPointer<vtkDoubleArray>::New();
  radius->SetName("Radius");
  auto arcLength = vtkSmartPointer<vtkDoubleArray>::New();
  arcLength->SetName("ArcLength");
  auto branchId = vtkSmartPointer<vtkIntArray>::New();
  branchId->SetName("Branch");
  auto parentId = vtkSmartPointer<vtkIntArray>::New();
  parentId->SetName("ParentBranch");
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  std::vector<vtkIdType> firstId(branches.size());
  for (size_t b = 0; b < branches.size(); ++b) {
    const medial::Centerline& centerline = branches[b];
    firstId[b] = points->GetNumberOfPoints();
    vtkIdType junction = -1;
    if (parents[b] >= 0) {
      const medial::Centerline& parent = branches[size_t(parents[b])];
      size_t nearest = 0;
      for (size_t k = 1; k < parent.points.size(); ++k)
        if ((parent.points[k] - centerline.points[0]).squaredNorm() < (parent.points[nearest] - centerline.points[0]).squaredNorm())
          nearest = k;
      junction = firstId[size_t(parents[b])] + vtkIdType(nearest);
    }
    lines->InsertNextCell(vtkIdType(centerline.points.size()) + (junction >= 0 ? 1 : 0));
    if (junction >= 0) lines->InsertCellPoint(junction);
    for (size_t k = 0; k < centerline.points.size(); ++k) {
      const auto& q = centerline.points[k];
      lines->InsertCellPoint(points->InsertNextPoint(q.x(), q.y(), q.z()));
      radius->InsertNextValue(centerline.radius[k]);
      arcLength->InsertNextValue(centerline.arcLength[k]);
    }
    branchId->InsertNextValue(int(b));
    parentId->InsertNextValue(parents[b]);
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(radius);
  output->GetPointData()->AddArray(arcLength);
  if (this->DetectBranches) {
    output->GetCellData()->AddArray(branchId);
    output->GetCellData()->AddArray(parentId);
  }
  const medial::Centerline& centerline = branches.front();
  if (this->ComputeSections && !this->WriteSections(volume, centerline.points, outputVector)) return 0;
  this->UpdateProgress(1.0);
  return 1;
}

bool vtkMedialTskCenterline::FollowTube(const medial::BinaryVolume& volume, int64_t seed, const medial::TskParameters& p,
                                        std::vector<medial::Centerline>& branches, std::vector<int>& parents) {
  const medial::TubularClusters clusters = medial::structureTube(volume, seed, [this](double f) {
    this->UpdateProgress(0.1 + 0.7 * f);
    return !this->GetAbortExecute();
  });
  if (!clusters.ok()) {
    vtkErrorMacro(<< clusters.error);
    return false;
  }
  this->PrimitiveCenterlinePoints = int(clusters.primitive.size());
  branches = {medial::tskAxis(volume, clusters, p)};
  parents = {-1};
  if (branches.front().points.size() < 2) {
    vtkErrorMacro(<< "the structure is too small for a centerline");
    return false;
  }
  return true;
}

bool vtkMedialTskCenterline::FollowBranches(const medial::BinaryVolume& volume, int64_t seed,
                                            const medial::TskParameters& p, std::vector<medial::Centerline>& branches,
                                            std::vector<int>& parents) {
  // Side branches shorter than MinimumBranchLength (default: twice the structure's largest inscribed
  // radius) stay part of the branch they leave.
  const std::vector<float> distance = medial::distanceToOutside(volume);
  double minimum = this->MinimumBranchLength;
  if (!(minimum > 0)) minimum = 2.0 * double(*std::max_element(distance.begin(), distance.end()));
  const medial::BranchVolumes split = medial::splitBranches(
      volume, seed, std::max(2, int(std::ceil(minimum / volume.spacing.minCoeff()))), &distance);
  if (!split.ok()) {
    vtkErrorMacro(<< split.error);
    return false;
  }
  this->PrimitiveCenterlinePoints = 0;
  std::vector<int> index(split.voxels.size(), -1);  // split branch -> output branch
  for (size_t b = 0; b < split.voxels.size(); ++b) {
    this->UpdateProgress(0.1 + 0.8 * double(b) / double(split.voxels.size()));
    if (this->GetAbortExecute()) return false;
    medial::BinaryVolume part = volume;
    std::fill(part.inside.begin(), part.inside.end(), 0);
    for (int64_t voxel : split.voxels[b]) part.inside[size_t(voxel)] = 1;
    const medial::TubularClusters clusters = medial::structureTube(part, split.start[b]);
    if (!clusters.ok()) continue;  // a branch too small to follow: its parent's line covers it
    medial::Centerline line = medial::tskAxis(part, clusters, p);
    if (line.points.size() < 2) continue;
    const int parent = split.parent[b] >= 0 ? index[size_t(split.parent[b])] : -1;
    if (split.parent[b] >= 0 && parent < 0) continue;  // its parent was dropped
    this->PrimitiveCenterlinePoints += int(clusters.primitive.size());
    index[b] = int(branches.size());
    branches.push_back(std::move(line));
    parents.push_back(parent);
  }
  if (branches.empty()) {
    vtkErrorMacro(<< "the structure is too small for a centerline");
    return false;
  }
  return true;
}

bool vtkMedialTskCenterline::WriteSections(const medial::BinaryVolume& volume,
                                           const std::vector<Eigen::Vector3d>& axis,
                                           vtkInformationVector* outputVector) {
  medial::SectionParameters parameters;
  parameters.spacing = this->SectionSpacing;
  parameters.rays = this->SectionRays;
  const medial::TubeSections sections = medial::tubeSections(volume, axis, parameters, [this](double f) {
    this->UpdateProgress(0.9 + 0.1 * f);
    return !this->GetAbortExecute();
  });
  if (sections.arcLength.empty()) {
    if (!this->GetAbortExecute()) vtkErrorMacro(<< "no section could be computed along the centerline");
    return false;
  }
  // Port 1: the profile, one row per section.
  vtkTable* table = vtkTable::GetData(outputVector, 1);
  const char* names[5] = {"ArcLength", "MinDiameter", "MaxDiameter", "Perimeter", "Area"};
  const std::vector<double>* columns[5] = {&sections.arcLength, &sections.minDiameter, &sections.maxDiameter,
                                           &sections.perimeter, &sections.area};
  for (int c = 0; c < 5; ++c) {
    auto column = vtkSmartPointer<vtkDoubleArray>::New();
    column->SetName(names[c]);
    for (double v : *columns[c]) column->InsertNextValue(v);
    table->AddColumn(column);
  }
  // Port 2: the unfolded wall, angle along x and arc length along y.
  vtkImageData* terrain = vtkImageData::GetData(outputVector, 2);
  const int rays = sections.rays, count = int(sections.arcLength.size());
  terrain->SetDimensions(rays, count, 1);
  terrain->SetSpacing(360.0 / rays, this->SectionSpacing, 1.0);
  auto distance = vtkSmartPointer<vtkDoubleArray>::New();
  distance->SetName("WallDistance");
  distance->SetNumberOfValues(vtkIdType(rays) * count);
  for (int y = 0; y < count; ++y)
    for (int x = 0; x < rays; ++x) distance->SetValue(vtkIdType(y) * rays + x, sections.wall[size_t(y)][size_t(x)]);
  terrain->GetPointData()->SetScalars(distance);
  return true;
}
