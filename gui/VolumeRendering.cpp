#include "VolumeRendering.h"

#include "MedialVolumeRendering.h"

#include <vtkVolume.h>

namespace medial::gui {

QStringList volumePresetNames() { return {"CT bone", "CT soft tissue and skin", "Full range"}; }

vtkSmartPointer<vtkVolume> makeVolumeRendering(vtkImageData* image, VolumePreset preset) {
  // The presets live with the scene (filters/MedialVolumeRendering), so `medial render` looks alike.
  return medial::makeVolumeRendering(image, static_cast<VolumeStyle>(static_cast<int>(preset) + 1));
}

}  // namespace medial::gui
