/**
 * @class vtkMedialINRReader
 * @brief Reads INRIMAGE volumes (.inr, .inr.gz) through CGAL's ImageIO (Debian's ITK has no INRIMAGE
 * reader). Voxel size and the header's translation (XO/YO/ZO) become spacing and origin; the voxel type
 * is kept (8/16/32-bit integers, signed or not, float, double). Vector images are rejected.
 */
#pragma once

#include "vtkMedialImageFileReader.h"

class MEDIALFILTERS_EXPORT vtkMedialINRReader : public vtkMedialImageFileReader {
 public:
  static vtkMedialINRReader* New();
  vtkTypeMacro(vtkMedialINRReader, vtkMedialImageFileReader);

 protected:
  vtkMedialINRReader() = default;
  ~vtkMedialINRReader() override = default;
  bool ReadImage(const std::string& path, vtkImageData* image, std::string& error) override;

 private:
  vtkMedialINRReader(const vtkMedialINRReader&) = delete;
  void operator=(const vtkMedialINRReader&) = delete;
};
