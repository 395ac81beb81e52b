// Runs a command line through the shell and captures its exit code, stdout and stderr.
#pragma once

#include <string>

namespace medial::test {

struct CommandResult {
  int exitCode = -1;
  std::string out, err;
};

CommandResult runCommand(const std::string& commandLine);

// The built binaries.
inline std::string medialExe() { return std::string(MEDIAL_BINARY_DIR) + "/bin/medial"; }
inline std::string medialGuiExe() { return std::string(MEDIAL_BINARY_DIR) + "/bin/medial-gui"; }

}  // namespace medial::test
