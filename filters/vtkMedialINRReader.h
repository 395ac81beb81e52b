/// \class vtkMedialINRReader
/// \brief Reads INRIMAGE volumes (.inr, .inr.gz) through CGAL's ImageIO (Debian's ITK has no INRIMAGE
/// reader). Voxel size and the header's translation (XO/YO/ZO) become spacing and origin; the voxel type
/// is kept (8/16/32-bit integers, signed or not, float, double). Vector images are rejected.
#pragma once

#include "vtkMedialImageFileReader.h"

class MEDIALFILTERS_EXPORT vtkMedialINRReader : public vtkMedialImageFileReader {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialINRReader* New();
  vtkTypeMacro(vtkMedialINRReader, vtkMedialImageFileReader);
  ///@}

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialINRReader() = default;
  ~vtkMedialINRReader() override = default;
  ///@}
  bool ReadImage(const std::string& path, vtkImageData* image, std::string& error) override;

 private:
  vtkMedialINRReader(const vtkMedialINRReader&) = delete;
  void operator=(const vtkMedialINRReader&) = delete;
};
