#include "MedialLumenSurface.h"

#include "centerline/BinaryVolume.h"

#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkQuadricDecimation.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace medial {

namespace {

// The mask averaged over blocks of `factor`^3 voxels, as levels 0..255 (the share of the block inside),
// padded by a layer of zeros so that the surface closes; in the mask's index space (a block's value sits
// at its centre).
vtkSmartPointer<vtkImageData> occupancyImage(const BinaryVolume& mask, int factor) {
  int dims[3];
  for (int a = 0; a < 3; ++a) dims[a] = (mask.size[a] + factor - 1) / factor + 2;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims);
  image->SetSpacing(factor, factor, factor);
  const double centre = -factor + 0.5 * (factor - 1);  // index-space position of padded voxel 0
  image->SetOrigin(centre, centre, centre);
  auto values = vtkSmartPointer<vtkUnsignedCharArray>::New();
  values->SetNumberOfValues(vtkIdType(dims[0]) * dims[1] * dims[2]);
  values->FillValue(0);
  std::vector<int> counts(size_t(dims[0]) * dims[1] * dims[2], 0);
  for (int k = 0; k < mask.size[2]; ++k)
    for (int j = 0; j < mask.size[1]; ++j) {
      const uint8_t* row = &mask.inside[size_t(mask.index(0, j, k))];
      const size_t out = (size_t(k / factor + 1) * dims[1] + size_t(j / factor + 1)) * dims[0] + 1;
      for (int i = 0; i < mask.size[0]; ++i) counts[out + size_t(i / factor)] += row[i] != 0;
    }
  const double full = double(factor) * factor * factor;
  for (size_t v = 0; v < counts.size(); ++v)
    values->SetValue(vtkIdType(v), uint8_t(std::lround(255.0 * counts[v] / full)));
  image->GetPointData()->SetScalars(values);
  return image;
}

// The block size that brings the voxel surface near `triangles` (a surface voxel face gives about two
// triangles, a coarser grid a factor squared fewer): decimating far more than needed costs seconds.
int blockFactor(const BinaryVolume& mask, int triangles) {
  if (triangles <= 0) return 1;
  int64_t faces = 0;  // x faces between inside and outside, a third of the surface roughly
  for (size_t v = 1; v < mask.inside.size(); ++v) faces += mask.inside[v] != mask.inside[v - 1];
  const double expected = 2.0 * 3.0 * double(faces);
  return std::clamp(int(std::floor(std::sqrt(expected / (1.5 * triangles)))), 1, 4);
}

// Index space to physical: origin + direction * (spacing .* index).
vtkSmartPointer<vtkTransform> physicalFrame(const BinaryVolume& mask) {
  auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) matrix->SetElement(r, c, mask.direction(r, c) * mask.spacing[c]);
    matrix->SetElement(r, 3, mask.origin[r]);
  }
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->SetMatrix(matrix);
  return transform;
}

}  // namespace

vtkSmartPointer<vtkPolyData> lumenSurface(const BinaryVolume& mask, const LumenSurfaceParameters& parameters,
                                          const std::function<bool(double)>& progress) {
  auto empty = vtkSmartPointer<vtkPolyData>::New();
  if (mask.inside.empty() || mask.inside.size() != size_t(mask.voxelCount())) return empty;
  const auto report = [&progress](double f) { return !progress || progress(f); };
  // Half occupancy: the boundary at sub-voxel precision on a coarser grid.
  auto contour = vtkSmartPointer<vtkFlyingEdges3D>::New();
  contour->SetInputData(occupancyImage(mask, blockFactor(mask, parameters.maximumTriangles)));
  contour->SetValue(0, 127.5);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  vtkSmartPointer<vtkPolyData> surface = contour->GetOutput();
  if (surface->GetNumberOfPolys() == 0 || !report(0.3)) return empty;
  if (parameters.smoothingIterations > 0) {
    auto smooth = vtkSmartPointer<vtkWindowedSincPolyDataFilter>::New();
    smooth->SetInputData(surface);
    smooth->SetNumberOfIterations(parameters.smoothingIterations);
    smooth->SetPassBand(parameters.passBand);
    smooth->BoundarySmoothingOff();
    smooth->FeatureEdgeSmoothingOff();
    smooth->NonManifoldSmoothingOn();
    smooth->NormalizeCoordinatesOn();
    smooth->Update();
    surface = smooth->GetOutput();
  }
  if (!report(0.6)) return empty;
  const vtkIdType triangles = surface->GetNumberOfPolys();
  if (parameters.maximumTriangles > 0 && triangles > parameters.maximumTriangles) {
    auto decimate = vtkSmartPointer<vtkQuadricDecimation>::New();
    decimate->SetInputData(surface);
    decimate->SetTargetReduction(1.0 - double(parameters.maximumTriangles) / double(triangles));
    decimate->VolumePreservationOn();
    decimate->Update();
    surface = decimate->GetOutput();
  }
  if (!report(0.9)) return empty;
  auto place = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  place->SetInputData(surface);
  place->SetTransform(physicalFrame(mask));
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputConnection(place->GetOutputPort());
  normals->SplittingOff();  // no duplicated points: the surface stays closed
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOn();  // outward, whatever the frame's handedness
  normals->Update();
  vtkSmartPointer<vtkPolyData> result = normals->GetOutput();
  report(1.0);
  return result;
}

}  // namespace medial
