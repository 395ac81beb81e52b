#include "MedialFileNames.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace medial {

std::string fileExtension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char* compound : {".nii.gz", ".inr.gz", ".vtk.gz"}) {
    const size_t n = std::strlen(compound);
    if (name.size() > n && name.compare(name.size() - n, n, compound) == 0) return compound;
  }
  const size_t dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? std::string() : name.substr(dot);
}

namespace {

std::string temporarySiblingName(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  // Keep the extension last: some writers look at it.
  return dir + ".tmp-" + std::to_string(::getpid()) + "-" + name;
}

}  // namespace

bool writeAtomically(const std::string& path,
                     const std::function<bool(const std::string& temporary, std::string& error)>& write,
                     std::string& error) {
  const std::string temporary = temporarySiblingName(path);
  error.clear();
  bool ok = write(temporary, error);
  if (ok && std::rename(temporary.c_str(), path.c_str()) != 0) {
    error = "cannot rename " + temporary + " to " + path + ": " + std::strerror(errno);
    ok = false;
  }
  if (!ok) std::remove(temporary.c_str());  // nothing to remove when the writer could not create it
  return ok;
}

}  // namespace medial
