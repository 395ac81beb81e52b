// `medial`: Medial's batch command (docs/ARCHITECTURE.md §6). Dispatches to one subcommand per algorithm.
#include "Commands.h"
#include "CommandLine.h"
#include "Interrupt.h"

#include <vtkLogger.h>
#include <vtkOutputWindow.h>
#include <vtkVersion.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#ifndef MEDIAL_VERSION
#define MEDIAL_VERSION "unknown"
#endif

namespace medial::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> all = {
      {"skeleton", "curve skeleton of a surface mesh by mesh contraction", skeletonUsage, skeletonOptions,
       runSkeleton},
      {"centerline", "TSK centerline of a tubular structure in a CT or label volume", centerlineUsage,
       centerlineOptions, runCenterline},
      {"sqm", "quad-dominant tube mesh of a skeleton with radii (SQM)", sqmUsage, sqmOptions, runSqm},
      {"sketch", "animatable skeleton and inflated mesh of closed 2-D strokes", sketchUsage, sketchOptions,
       runSketch},
      {"rig", "skinning weights binding any mesh to any skeleton, written as a rig", rigUsage, rigOptions,
       runRig},
      {"render", "render meshes, skeletons and volumes offscreen to a PNG", renderUsage, renderOptions,
       runRender},
  };
  return all;
}

namespace {

void printHelp(FILE* out) {
  std::fprintf(out,
               "medial %s: skeletons, centerlines, tube meshes and ghost views\n\n"
               "usage: medial COMMAND [ARGS...]\n"
               "       medial COMMAND --help\n"
               "       medial --help | --version\n\ncommands:\n",
               MEDIAL_VERSION);
  for (const Command& c : commands()) std::fprintf(out, "  %-11s %s\n", c.name, c.summary);
  std::fprintf(out, "  %-11s %s\n", "batch",
               "any of these commands over many files, locally or on a Dask cluster");
  std::fprintf(
      out,
      "\nExit status: 0 success, 1 failure (one line on stderr), 2 usage error, 130 cancelled (Ctrl-C).\n");
}

}  // namespace
}  // namespace medial::cli

int main(int argc, char** argv) {
  using namespace medial::cli;
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    printHelp(stderr);
    return kUsageError;
  }
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    printHelp(stdout);
    return kSuccess;
  }
  if (args[0] == "--version") {
    std::printf("medial %s (VTK %s)\n", MEDIAL_VERSION, vtkVersion::GetVTKVersion());
    return kSuccess;
  }
  if (args[0] == "batch") return runBatch(argv[0], std::vector<std::string>(args.begin() + 1, args.end()));
  const Command* command = nullptr;
  for (const Command& c : commands())
    if (args[0] == c.name) command = &c;
  if (!command) {
    std::fprintf(stderr, "medial: unknown command '%s' (see medial --help)\n", args[0].c_str());
    return kUsageError;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  for (const std::string& a : rest)
    if (a == "--help" || a == "-h") {
      std::fputs(command->usage().c_str(), stdout);
      return kSuccess;
    }
  // For programs that pass options through (medial batch): which take a value, which are flags.
  if (rest.size() == 1 && rest[0] == "--list-options") {
    const OptionSpec& spec = command->options();
    std::printf("values");
    for (const std::string& option : spec.withValue) std::printf(" %s", option.c_str());
    std::printf("\nflags");
    for (const std::string& option : spec.flags) std::printf(" %s", option.c_str());
    std::printf("\n");
    return kSuccess;
  }

  // Errors are reported once, by the command, in one line: VTK's own multi-line reports do not reach
  // the terminal. (GlobalWarningDisplayOff would also silence the ErrorEvent observers the command reads.)
  // MEDIAL_VTK_LOG=1 keeps them, for diagnosing VTK itself.
  const char* vtkLog = std::getenv("MEDIAL_VTK_LOG");
  if (!vtkLog || std::strcmp(vtkLog, "1") != 0) {
    vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);  // the executive's "returned failure" reports
  }
  if (std::strcmp(command->name, "render") != 0) catchInterrupts();  // render runs no filter (Interrupt.h)
  try {
    return command->run(rest);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "medial %s: %s (see 'medial %s --help')\n", command->name, e.what(), command->name);
    return kUsageError;
  } catch (const Cancelled& e) {
    std::fprintf(stderr, "medial %s: %s\n", command->name, e.what());
    return kCancelled;
  } catch (const Failure& e) {
    std::fprintf(stderr, "medial %s: %s\n", command->name, e.what());
    return kFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "medial %s: %s\n", command->name, e.what());
    return kFailure;
  }
}
