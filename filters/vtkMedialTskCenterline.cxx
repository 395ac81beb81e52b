#include "vtkMedialTskCenterline.h"

#include "centerline/TskAxis.h"
#include "centerline/TubeSections.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
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
  const medial::TubularClusters clusters = medial::structureTube(volume, seed, [this](double f) {
    this->UpdateProgress(0.1 + 0.7 * f);
    return !this->GetAbortExecute();
  });
  if (!clusters.ok()) {
    vtkErrorMacro(<< clusters.error);
    return 0;
  }
  this->PrimitiveCenterlinePoints = int(clusters.primitive.size());
  medial::TskParameters p;
  p.antecedentWidth = this->AntecedentWidth;
  p.sampleSpacing = this->SampleSpacing;
  p.centeringIterations = this->CenteringIterations;
  const medial::Centerline centerline = medial::tskAxis(volume, clusters, p);
  if (centerline.points.size() < 2) {
    vtkErrorMacro(<< "the structure is too small for a centerline");
    return 0;
  }

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto radius = vtkSmartPointer<vtkDoubleArray>::New();
  radius->SetName("Radius");
  auto arcLength = vtkSmartPointer<vtkDoubleArray>::New();
  arcLength->SetName("ArcLength");
  auto line = vtkSmartPointer<vtkCellArray>::New();
  line->InsertNextCell(vtkIdType(centerline.points.size()));
  for (size_t k = 0; k < centerline.points.size(); ++k) {
    const auto& q = centerline.points[k];
    line->InsertCellPoint(points->InsertNextPoint(q.x(), q.y(), q.z()));
    radius->InsertNextValue(centerline.radius[k]);
    arcLength->InsertNextValue(centerline.arcLength[k]);
  }
  output->SetPoints(points);
  output->SetLines(line);
  output->GetPointData()->AddArray(radius);
  output->GetPointData()->AddArray(arcLength);
  if (this->ComputeSections && !this->WriteSections(volume, centerline.points, outputVector)) return 0;
  this->UpdateProgress(1.0);
  return 1;
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
