/// \file
/// Small helpers about file names shared by the readers, the writers and the command line.
#pragma once

#include <functional>
#include <string>

namespace medial {

/// The lower-case extension including compound ones: "mesh.OFF" -> ".off", "ct.nii.gz" -> ".nii.gz".
std::string fileExtension(const std::string& path);

/// Writes `path` so that a reader never sees a partial file and a failure leaves nothing behind:
/// `write(temporary, error)` writes a temporary file next to `path` (same directory, so that the rename is
/// atomic) and returns false with a reason on failure; then the temporary file replaces `path`. On any
/// failure the temporary file is removed and `error` holds the reason. (docs/ARCHITECTURE.md §6)
bool writeAtomically(const std::string& path,
                     const std::function<bool(const std::string& temporary, std::string& error)>& write,
                     std::string& error);

}  // namespace medial
