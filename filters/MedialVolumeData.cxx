#include "MedialVolumeData.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkType.h>

namespace medial {

namespace {

bool scalarType(int vtkType, ScalarVolume::Type& type) {
  using Type = ScalarVolume::Type;
  switch (vtkType) {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
      type = Type::Int8;
      return true;
    case VTK_UNSIGNED_CHAR:
      type = Type::UInt8;
      return true;
    case VTK_SHORT:
      type = Type::Int16;
      return true;
    case VTK_UNSIGNED_SHORT:
      type = Type::UInt16;
      return true;
    case VTK_INT:
      type = Type::Int32;
      return true;
    case VTK_UNSIGNED_INT:
      type = Type::UInt32;
      return true;
    case VTK_LONG:
      type = sizeof(long) == 8 ? Type::Int64 : Type::Int32;
      return true;
    case VTK_UNSIGNED_LONG:
      type = sizeof(long) == 8 ? Type::UInt64 : Type::UInt32;
      return true;
    case VTK_LONG_LONG:
    case VTK_ID_TYPE:
      type = Type::Int64;
      return true;
    case VTK_UNSIGNED_LONG_LONG:
      type = Type::UInt64;
      return true;
    case VTK_FLOAT:
      type = Type::Float32;
      return true;
    case VTK_DOUBLE:
      type = Type::Float64;
      return true;
    default:
      return false;
  }
}

}  // namespace

bool scalarVolumeOf(vtkImageData* image, ScalarVolume& volume, std::string& error) {
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  int dims[3] = {0, 0, 0};
  if (image) image->GetDimensions(dims);
  volume.size = {dims[0], dims[1], dims[2]};
  if (!scalars) return true;  // no voxels: the algorithm reports the empty volume
  if (!scalarType(scalars->GetDataType(), volume.type)) {
    error = std::string("voxels of type ") + scalars->GetDataTypeAsString() + " are not supported";
    return false;
  }
  volume.voxels = scalars->GetVoidPointer(0);
  volume.components = scalars->GetNumberOfComponents();
  double value[3];
  image->GetOrigin(value);
  volume.origin = Eigen::Vector3d(value[0], value[1], value[2]);
  image->GetSpacing(value);
  volume.spacing = Eigen::Vector3d(value[0], value[1], value[2]);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) volume.direction(r, c) = image->GetDirectionMatrix()->GetElement(r, c);
  return true;
}

}  // namespace medial
