#include "vtkMedialInVesaliusReader.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <cmath>

#include <archive.h>
#include <archive_entry.h>

#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialInVesaliusReader);

namespace {

// Reads the content of the first archive member whose name satisfies `wanted`. Returns false when the
// archive cannot be read or has no such member.
bool readArchiveMember(const std::string& path, const std::function<bool(const std::string&)>& wanted,
                       std::string& content, std::string& error) {
  std::unique_ptr<archive, decltype(&archive_read_free)> reader(archive_read_new(), &archive_read_free);
  archive_read_support_filter_all(reader.get());
  archive_read_support_format_tar(reader.get());
  if (archive_read_open_filename(reader.get(), path.c_str(), 1 << 16) != ARCHIVE_OK) {
    error = std::string("not an InVesalius project (a gzip tar): ") + archive_error_string(reader.get());
    return false;
  }
  archive_entry* entry = nullptr;
  int status;
  while ((status = archive_read_next_header(reader.get(), &entry)) == ARCHIVE_OK) {
    if (!wanted(archive_entry_pathname(entry))) continue;
    content.resize(static_cast<size_t>(archive_entry_size(entry)));
    const la_ssize_t got = archive_read_data(reader.get(), content.data(), content.size());
    if (got != static_cast<la_ssize_t>(content.size())) {
      error = std::string("truncated member ") + archive_entry_pathname(entry);
      return false;
    }
    return true;
  }
  error = status == ARCHIVE_EOF ? "member not found" : archive_error_string(reader.get());
  return false;
}

std::string baseName(const std::string& name) {
  const size_t slash = name.find_last_of('/');
  return slash == std::string::npos ? name : name.substr(slash + 1);
}

// The value element that follows <key>name</key> in a plist <dict>, or null.
vtkXMLDataElement* plistValue(vtkXMLDataElement* dict, const std::string& name) {
  if (!dict) return nullptr;
  for (int i = 0; i + 1 < dict->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* key = dict->GetNestedElement(i);
    if (std::strcmp(key->GetName(), "key") == 0 && key->GetCharacterData() && name == key->GetCharacterData())
      return dict->GetNestedElement(i + 1);
  }
  return nullptr;
}

std::vector<double> plistNumbers(vtkXMLDataElement* array) {
  std::vector<double> values;
  if (!array || std::strcmp(array->GetName(), "array") != 0) return values;
  for (int i = 0; i < array->GetNumberOfNestedElements(); ++i) {
    const char* text = array->GetNestedElement(i)->GetCharacterData();
    values.push_back(text ? std::atof(text) : 0.0);
  }
  return values;
}

int vtkTypeOfNumpy(const std::string& dtype, int& bytes) {
  struct Entry {
    const char* name;
    int type;
    int bytes;
  };
  static const Entry table[] = {{"int8", VTK_SIGNED_CHAR, 1}, {"uint8", VTK_UNSIGNED_CHAR, 1},
                                {"int16", VTK_SHORT, 2},      {"uint16", VTK_UNSIGNED_SHORT, 2},
                                {"int32", VTK_INT, 4},        {"uint32", VTK_UNSIGNED_INT, 4},
                                {"float32", VTK_FLOAT, 4},    {"float64", VTK_DOUBLE, 8}};
  for (const Entry& e : table)
    if (dtype == e.name) {
      bytes = e.bytes;
      return e.type;
    }
  return -1;
}

}  // namespace

bool vtkMedialInVesaliusReader::ReadImage(const std::string& path, vtkImageData* image, std::string& error) {
  std::string plistText;
  if (!readArchiveMember(
          path, [](const std::string& n) { return baseName(n) == "main.plist"; }, plistText, error)) {
    if (error == "member not found") error = "no main.plist: not an InVesalius project";
    return false;
  }
  vtkSmartPointer<vtkXMLDataElement> plist;
  plist.TakeReference(vtkXMLUtilities::ReadElementFromString(plistText.c_str()));
  vtkXMLDataElement* dict = plist ? plist->FindNestedElementWithName("dict") : nullptr;
  vtkXMLDataElement* matrix = plistValue(dict, "matrix");
  vtkXMLDataElement* dtypeElement = plistValue(matrix, "dtype");
  vtkXMLDataElement* fileElement = plistValue(matrix, "filename");
  const std::vector<double> shape = plistNumbers(plistValue(matrix, "shape"));
  const std::vector<double> spacing = plistNumbers(plistValue(dict, "spacing"));
  if (!dtypeElement || !fileElement || !dtypeElement->GetCharacterData() ||
      !fileElement->GetCharacterData() || shape.size() != 3 || spacing.size() != 3) {
    error = "main.plist lacks matrix dtype, filename, shape or spacing";
    return false;
  }
  int bytes = 0;
  const int type = vtkTypeOfNumpy(dtypeElement->GetCharacterData(), bytes);
  if (type < 0) {
    error = std::string("unsupported matrix dtype ") + dtypeElement->GetCharacterData();
    return false;
  }
  // Each extent a whole number of voxels a VTK image can index (fuzz_inv3 found 4e20, whose conversion to
  // int is undefined).
  for (double extent : shape)
    if (!(extent >= 1 && extent <= 1e9) || extent != std::floor(extent)) {
      error = "main.plist gives a matrix shape that is not three whole numbers from 1 to 10^9";
      return false;
    }
  const int nx = static_cast<int>(shape[2]), ny = static_cast<int>(shape[1]), nz = static_cast<int>(shape[0]);
  if (!(spacing[0] > 0 && spacing[1] > 0 && spacing[2] > 0)) {
    error = "main.plist gives an empty shape or a non-positive spacing";
    return false;
  }

  const std::string matrixName = fileElement->GetCharacterData();
  std::string voxels;
  if (!readArchiveMember(
          path, [&](const std::string& n) { return baseName(n) == matrixName; }, voxels, error)) {
    error = "cannot read the voxel matrix " + matrixName + ": " + error;
    return false;
  }
  const size_t expected = static_cast<size_t>(nx) * ny * nz * bytes;
  if (voxels.size() != expected) {
    error = matrixName + " holds " + std::to_string(voxels.size()) + " bytes, the shape needs " +
            std::to_string(expected);
    return false;
  }

  image->SetDimensions(nx, ny, nz);
  image->SetSpacing(spacing[0], spacing[1], spacing[2]);
  image->SetOrigin(0, 0, 0);
  image->AllocateScalars(type, 1);
  // InVesalius keeps its rows flipped with respect to DICOM: the face lies at high row indices. Flip them
  // back so that +y runs anterior to posterior and +z inferior to superior, as in DICOM's LPS space.
  const size_t rowBytes = static_cast<size_t>(nx) * bytes;
  auto* target = static_cast<char*>(image->GetScalarPointer());
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      std::memcpy(target + (static_cast<size_t>(z) * ny + y) * rowBytes,
                  voxels.data() + (static_cast<size_t>(z) * ny + (ny - 1 - y)) * rowBytes, rowBytes);
  // (little-endian data on a little-endian host: no byte swapping)
  image->GetPointData()->GetScalars()->SetName("ImageScalars");
  return true;
}
