/// \file
/// MedialVolumeRendering: a ray-cast 3-D rendering of a scalar volume (vtkSmartVolumeMapper: GPU ray
/// casting, which Mesa's llvmpipe also runs) with transfer-function presets for CT and for any other
/// volume. vtkMedialScene (VolumeStyle), `medial render --volume-rendering` and the GUI use it; the ghost
/// pass ghosts it like any occluder (a CT volume as context).
#pragma once

#include <vtkSmartPointer.h>

#include <string>

class vtkImageData;
class vtkVolume;

namespace medial {

/// 0 is no rendering (vtkMedialScene draws three slices); the others are presets.
enum class VolumeStyle { Slices = 0, CtBone = 1, CtSoftTissue = 2, FullRange = 3 };

///@{
/// "slices", "ct-bone", "ct-soft-tissue", "full-range"; parse returns false for any other name.
const char* volumeStyleName(VolumeStyle style);
bool parseVolumeStyle(const std::string& name, VolumeStyle& style);
///@}

/// A vtkVolume showing `image` with a preset's colour and opacity transfer functions (Hounsfield units for
/// the CT presets; FullRange ramps over the image's own range). Null for VolumeStyle::Slices.
vtkSmartPointer<vtkVolume> makeVolumeRendering(vtkImageData* image, VolumeStyle style);

}  // namespace medial
