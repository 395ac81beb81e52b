// Small helpers about file names shared by the readers, the writers and the command line.
#pragma once

#include <string>

namespace medial {

// The lower-case extension including compound ones: "mesh.OFF" -> ".off", "ct.nii.gz" -> ".nii.gz".
std::string fileExtension(const std::string& path);

// A temporary name next to `path` (same directory, so that rename() is atomic).
std::string temporarySiblingName(const std::string& path);

// Renames `from` to `to`, replacing `to`. Returns false and removes `from` on failure.
bool replaceFile(const std::string& from, const std::string& to, std::string& error);

}  // namespace medial
