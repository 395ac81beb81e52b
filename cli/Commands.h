// The subcommands of `medial` (docs/ARCHITECTURE.md §6). Each returns an exit code or throws UsageError /
// Failure.
#pragma once

#include <string>
#include <vector>

namespace medial::cli {

struct Command {
  const char* name;
  const char* summary;
  std::string usage;  // the full --help text
  int (*run)(const std::vector<std::string>& args);
};

const std::vector<Command>& commands();

int runRender(const std::vector<std::string>& args);
int runSkeleton(const std::vector<std::string>& args);
int runSqm(const std::vector<std::string>& args);
int runCenterline(const std::vector<std::string>& args);
int runSketch(const std::vector<std::string>& args);
int runRig(const std::vector<std::string>& args);
// Hands `medial batch ARGS` to the Python batch runner (medial/batch.py); returns only on failure.
int runBatch(const char* self, const std::vector<std::string>& args);

}  // namespace medial::cli
