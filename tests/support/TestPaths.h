// Where tests find the source tree, the build tree and sample data.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace medial::test {

inline std::string sourceDir() { return MEDIAL_SOURCE_DIR; }
inline std::string binaryDir() { return MEDIAL_BINARY_DIR; }
inline std::string dataPath(const std::string& relative) { return sourceDir() + "/data/" + relative; }
inline std::string externalPath(const std::string& relative) {
  return sourceDir() + "/data/external/" + relative;
}

// A fresh, empty directory for one test's files under the build tree.
inline std::string scratchDir(const std::string& name) {
  const std::string dir = binaryDir() + "/test-scratch/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Runs `medial-make-colon-phantom ARGUMENTS` (output directory, optional volume file, options) quietly;
// true when it succeeded.
inline bool makeColonPhantom(const std::string& arguments) {
  return std::system(
             (binaryDir() + "/bin/medial-make-colon-phantom " + arguments + " > /dev/null").c_str()) == 0;
}

inline bool hasDisplay() {
  const char* display = std::getenv("DISPLAY");
  return display && *display;
}

}  // namespace medial::test

// Skips a test whose external sample is absent (scripts/fetch-samples extracts them).
#define MEDIAL_REQUIRE_FILE(path)     \
  if (!std::filesystem::exists(path)) \
  GTEST_SKIP() << "sample " << (path) << " is absent: run scripts/fetch-samples"

#define MEDIAL_REQUIRE_DISPLAY() \
  if (!medial::test::hasDisplay()) GTEST_SKIP() << "no X display: run the tests under xvfb-run -a"
