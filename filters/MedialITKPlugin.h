/// \file
/// Volume reading through ITK lives in a library of its own, libMedialITKIO.so (filters/itk/), next to
/// libMedialFilters.so, loaded the first time a volume is read: ITK and GDCM cost each process time at
/// start, and most runs of `medial` (meshes, skeletons, sketches) never read a volume.
#pragma once

#include <string>

class vtkImageData;

/// What libMedialITKIO exports: reads `path` (a file, or a DICOM series directory: the series `seriesUid`,
/// or when empty the one with the most files) into `image`. Returns false with `error` set.
using MedialReadVolumeFunction = bool (*)(const std::string& path, const std::string& seriesUid,
                                          vtkImageData* image, std::string& error);

namespace medial {

/// Calls libMedialITKIO's reader, loading the library on first use. When it cannot be loaded: false, and
/// `error` names the library and why.
bool readVolumeWithITK(const std::string& path, const std::string& seriesUid, vtkImageData* image,
                       std::string& error);

}  // namespace medial
