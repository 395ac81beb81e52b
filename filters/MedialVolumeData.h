/// \file
/// Conversion of a vtkImageData into the plain ScalarVolume of src/: a typed view of its voxels (no copy)
/// with its origin, spacing and direction (docs/ARCHITECTURE.md §4).
#pragma once

#include "centerline/TskCenterline.h"

#include <string>

class vtkImageData;

namespace medial {

/// The view of `image`'s point scalars (`voxels` null when it has none); false with a reason for a type
/// not supported (every integer and floating-point type is).
bool scalarVolumeOf(vtkImageData* image, ScalarVolume& volume, std::string& error);

}  // namespace medial
