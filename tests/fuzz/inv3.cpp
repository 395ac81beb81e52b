// Fuzz target: vtkMedialInVesaliusReader on a project whose main.plist is the fuzz input (packed with a
// small matrix.dat into a gzipped tar, as InVesalius writes them). It must report an error or give an
// image, never crash, and never allocate for a shape the data cannot hold.
#include "vtkMedialInVesaliusReader.h"

#include <archive.h>
#include <archive_entry.h>
#include <unistd.h>

#include <vtkImageData.h>
#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <string>
#include <vector>

namespace {

void addMember(archive* out, const char* name, const void* data, size_t size) {
  archive_entry* entry = archive_entry_new();
  archive_entry_set_pathname(entry, name);
  archive_entry_set_size(entry, la_int64_t(size));
  archive_entry_set_filetype(entry, AE_IFREG);
  archive_entry_set_perm(entry, 0644);
  archive_write_header(out, entry);
  archive_write_data(out, data, size);
  archive_entry_free(entry);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vtkObject::GlobalWarningDisplayOff();
  const std::string path = "/tmp/medial-fuzz-" + std::to_string(::getpid()) + ".inv3";
  archive* out = archive_write_new();
  archive_write_add_filter_gzip(out);
  archive_write_set_format_pax_restricted(out);
  archive_write_open_filename(out, path.c_str());
  addMember(out, "main.plist", data, size);
  const std::vector<int16_t> voxels(4 * 4 * 4, 100);
  addMember(out, "matrix.dat", voxels.data(), voxels.size() * sizeof(int16_t));
  archive_write_close(out);
  archive_write_free(out);
  auto reader = vtkSmartPointer<vtkMedialInVesaliusReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return 0;
}
