// `medial batch ...`: the batch runner is Python (medial/batch.py on Dask); this hands the arguments to
// Debian's interpreter with the package of this installation (or build) on its path and this executable
// as the `medial` the tasks run. The script runs as a file, not as `-m medial.batch`: importing the
// package `medial` would load VTK and our filters into a driver that only starts processes.
#include "CommandLine.h"
#include "Commands.h"

#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace medial::cli {

int runBatch(const char*, const std::vector<std::string>& args) {
  char self[PATH_MAX] = {0};
  const ssize_t length = ::readlink("/proc/self/exe", self, sizeof self - 1);
  const std::string executable = length > 0 ? std::string(self, size_t(length)) : std::string("medial");
  const std::string bin = executable.substr(0, executable.find_last_of('/'));
  const std::string package = bin + "/../lib/python3/dist-packages";  // installed and build trees alike
  const char* old = std::getenv("PYTHONPATH");
  ::setenv("PYTHONPATH", (package + (old && *old ? ":" + std::string(old) : "")).c_str(), 1);
  ::setenv("MEDIAL_EXECUTABLE", executable.c_str(), 0);  // unless the caller names another (tests do)
  // argv[0] is the full path: Python derives sys.executable (which Dask's worker processes run) from it.
  std::vector<std::string> words = {"/usr/bin/python3", package + "/medial/batch.py"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  ::execv("/usr/bin/python3", argv.data());
  std::fprintf(stderr, "medial batch: cannot start /usr/bin/python3 (%s); it needs python3-distributed\n",
               std::strerror(errno));
  return kFailure;
}

}  // namespace medial::cli
