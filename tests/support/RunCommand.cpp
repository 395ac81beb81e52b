#include "RunCommand.h"

#include "TestPaths.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace medial::test {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

CommandResult runCommand(const std::string& commandLine) {
  static int counter = 0;
  const std::string base =
      binaryDir() + "/test-scratch/command-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  std::filesystem::create_directories(binaryDir() + "/test-scratch");
  const std::string full = "(" + commandLine + ") >" + base + ".out 2>" + base + ".err";
  const int status = std::system(full.c_str());
  CommandResult result;
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = slurp(base + ".out");
  result.err = slurp(base + ".err");
  std::filesystem::remove(base + ".out");
  std::filesystem::remove(base + ".err");
  return result;
}

}  // namespace medial::test
