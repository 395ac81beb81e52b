#include "MedialITKPlugin.h"

#include <dlfcn.h>

#include <mutex>

namespace medial {

namespace {

struct Plugin {
  MedialReadVolumeFunction read = nullptr;
  std::string error;  // why it could not be loaded
};

// libMedialITKIO.so from the directory of the library holding this code (build/lib or PREFIX/lib).
Plugin loadPlugin() {
  Plugin plugin;
  Dl_info self;
  std::string directory;
  if (::dladdr(reinterpret_cast<void*>(&readVolumeWithITK), &self) && self.dli_fname) {
    directory = self.dli_fname;
    directory.erase(directory.find_last_of('/') + 1);
  }
  const std::string path = directory + "libMedialITKIO.so";
  void* library = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    const char* why = ::dlerror();
    plugin.error = "cannot load Medial's volume reader " + path + " (" + (why ? why : "unknown") + ")";
    return plugin;
  }
  plugin.read = reinterpret_cast<MedialReadVolumeFunction>(::dlsym(library, "medialReadVolumeWithITK"));
  if (!plugin.read) plugin.error = path + " does not export medialReadVolumeWithITK";
  return plugin;  // the library stays loaded: ITK's factories live as long as the process
}

}  // namespace

bool readVolumeWithITK(const std::string& path, const std::string& seriesUid, vtkImageData* image,
                       std::string& error) {
  static std::once_flag once;
  static Plugin plugin;
  std::call_once(once, [] { plugin = loadPlugin(); });
  if (!plugin.read) {
    error = plugin.error;
    return false;
  }
  return plugin.read(path, seriesUid, image, error);
}

}  // namespace medial
