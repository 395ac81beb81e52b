// VolumeRendering: the GUI's names for the ray-cast volume presets of filters/MedialVolumeRendering.
#pragma once

#include <QStringList>

#include <vtkSmartPointer.h>

class vtkImageData;
class vtkVolume;

namespace medial::gui {

enum class VolumePreset { CtBone = 0, CtSoftTissue = 1, FullRange = 2 };

QStringList volumePresetNames();  // in VolumePreset order

// A vtkVolume showing `image` with a preset's color and opacity transfer functions (Hounsfield units for
// the CT presets; FullRange ramps over the image's own range).
vtkSmartPointer<vtkVolume> makeVolumeRendering(vtkImageData* image, VolumePreset preset);

}  // namespace medial::gui
