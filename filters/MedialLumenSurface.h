/// \file
/// MedialLumenSurface: the closed surface of a segmented structure (the TSK filter's followed lumen), made
/// as 3D Slicer makes a segment's closed surface: flying edges on the voxel mask, windowed-sinc smoothing
/// (the voxel staircase gone, the volume kept), quadric decimation to a triangle budget the fly-through
/// renders smoothly, and consistent normals; in physical coordinates (mm).
#pragma once

#include <vtkSmartPointer.h>

#include <functional>

class vtkPolyData;

namespace medial {

struct BinaryVolume;

/// How the lumen's surface is smoothed and decimated.
struct LumenSurfaceParameters {
  int smoothingIterations = 20;   ///< windowed sinc (0: the voxel surface as is)
  double passBand = 0.01;         ///< Slicer's smoothing factor 0.5
  int maximumTriangles = 100000;  ///< decimated above this (0: never)
};

/// The surface of the mask's voxels (closed when the mask's outer layer is background, as the TSK
/// filter's structure box is); empty polydata for an empty mask. `progress(fraction)` returning false
/// stops early (the result is then empty).
vtkSmartPointer<vtkPolyData> lumenSurface(const BinaryVolume& mask, const LumenSurfaceParameters& parameters,
                                          const std::function<bool(double)>& progress = {});

}  // namespace medial
