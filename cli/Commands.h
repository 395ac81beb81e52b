// The subcommands of `medial` (docs/ARCHITECTURE.md §6). Each returns an exit code or throws UsageError /
// Failure.
#pragma once

#include "CommandLine.h"

#include <string>
#include <vector>

namespace medial::cli {

struct Command {
  const char* name;
  const char* summary;
  const std::string& (*usage)();   // the full --help text
  const OptionSpec& (*options)();  // what parseArgs takes: the options with a value, and the flags
  int (*run)(const std::vector<std::string>& args);
};

const std::vector<Command>& commands();

// Each command's --help text, built once from a fresh filter's defaults (in the command's own file).
const std::string& skeletonUsage();
const std::string& centerlineUsage();
const std::string& sqmUsage();
const std::string& sketchUsage();
const std::string& rigUsage();
const std::string& renderUsage();
// Each command's options, in the command's own file: the one table its parsing and `--list-options` use.
const OptionSpec& skeletonOptions();
const OptionSpec& centerlineOptions();
const OptionSpec& sqmOptions();
const OptionSpec& sketchOptions();
const OptionSpec& rigOptions();
const OptionSpec& renderOptions();

int runRender(const std::vector<std::string>& args);
int runSkeleton(const std::vector<std::string>& args);
int runSqm(const std::vector<std::string>& args);
int runCenterline(const std::vector<std::string>& args);
int runSketch(const std::vector<std::string>& args);
int runRig(const std::vector<std::string>& args);
// Hands `medial batch ARGS` to the Python batch runner (medial/batch.py); returns only on failure.
int runBatch(const char* self, const std::vector<std::string>& args);

}  // namespace medial::cli
