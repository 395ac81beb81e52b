#include "vtkMedialINRReader.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>

#include <CGAL/Image_3.h>

#include <cstring>

vtkStandardNewMacro(vtkMedialINRReader);

namespace {

// VTK scalar type of a CGAL ImageIO voxel, or -1 when VTK has none.
int vtkTypeOf(const _image* image) {
  if (image->wordKind == WK_FLOAT) return image->wdim == 4 ? VTK_FLOAT : image->wdim == 8 ? VTK_DOUBLE : -1;
  if (image->wordKind != WK_FIXED) return -1;
  const bool isSigned = image->sign == SGN_SIGNED;
  switch (image->wdim) {
    case 1:
      return isSigned ? VTK_SIGNED_CHAR : VTK_UNSIGNED_CHAR;
    case 2:
      return isSigned ? VTK_SHORT : VTK_UNSIGNED_SHORT;
    case 4:
      return isSigned ? VTK_INT : VTK_UNSIGNED_INT;
    case 8:
      return isSigned ? VTK_LONG_LONG : VTK_UNSIGNED_LONG_LONG;
    default:
      return -1;
  }
}

}  // namespace

bool vtkMedialINRReader::ReadImage(const std::string& path, vtkImageData* image, std::string& error) {
  CGAL::Image_3 inr;
  if (!inr.read(path)) {
    error = "not a readable INRIMAGE file";
    return false;
  }
  const _image* header = inr.image();
  if (header->vdim != 1) {
    error = "the image has " + std::to_string(header->vdim) +
            " components per voxel; Medial reads scalar volumes";
    return false;
  }
  const int type = vtkTypeOf(header);
  if (type < 0) {
    error = "unsupported voxel type (" + std::to_string(header->wdim) + " bytes)";
    return false;
  }
  image->SetDimensions(static_cast<int>(inr.xdim()), static_cast<int>(inr.ydim()),
                       static_cast<int>(inr.zdim()));
  image->SetSpacing(inr.vx(), inr.vy(), inr.vz());
  image->SetOrigin(inr.tx(), inr.ty(), inr.tz());
  image->AllocateScalars(type, 1);
  std::memcpy(image->GetScalarPointer(), inr.data(), inr.size() * header->wdim);
  image->GetPointData()->GetScalars()->SetName("ImageScalars");
  return true;
}
