// Argument parsing and exit codes of the `medial` command (docs/ARCHITECTURE.md §6).
#pragma once

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace medial::cli {

// kCancelled: stopped by Ctrl-C (SIGINT) or SIGTERM before it finished, as shells report 128 + SIGINT.
enum ExitCode { kSuccess = 0, kFailure = 1, kUsageError = 2, kCancelled = 130 };

// A usage mistake: reported with the command's usage line, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A failure on valid usage (unreadable file, failed filter): one line on stderr, exit code 1.
struct Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The command stopped at the user's request (Interrupt.h): "cancelled" on stderr, exit code kCancelled.
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

struct OptionSpec {
  std::set<std::string> withValue;  // e.g. "-o", "--size"
  std::set<std::string> flags;      // e.g. "--quiet"
};

struct ParsedArgs {
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;                  // the last value of each option
  std::map<std::string, std::vector<std::string>> allValues;  // every value of a repeated option
  std::set<std::string> flags;

  bool has(const std::string& flag) const { return flags.count(flag) || values.count(flag); }
  std::string value(const std::string& option, const std::string& fallback = "") const {
    auto it = values.find(option);
    return it == values.end() ? fallback : it->second;
  }
  std::vector<std::string> all(const std::string& option) const {
    auto it = allValues.find(option);
    return it == allValues.end() ? std::vector<std::string>{} : it->second;
  }
};

// Accepts "--name value", "--name=value" and "-o value". Throws UsageError on an unknown option or a
// missing value. "--" ends the options.
ParsedArgs parseArgs(const std::vector<std::string>& args, const OptionSpec& spec);

// "800x600" -> {800, 600}; throws UsageError.
std::pair<int, int> parseSize(const std::string& text);
// "30,20" -> {30, 20}; throws UsageError naming `option`.
std::vector<double> parseNumbers(const std::string& text, size_t count, const std::string& option);

}  // namespace medial::cli
