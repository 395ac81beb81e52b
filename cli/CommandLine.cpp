#include "CommandLine.h"

#include <sstream>

namespace medial::cli {

ParsedArgs parseArgs(const std::vector<std::string>& args, const OptionSpec& spec) {
  ParsedArgs parsed;
  bool optionsEnded = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (optionsEnded || arg.size() < 2 || arg[0] != '-') {
      parsed.positional.push_back(arg);
      continue;
    }
    if (arg == "--") {
      optionsEnded = true;
      continue;
    }
    std::string name = arg, value;
    bool inlineValue = false;
    if (const size_t eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
      inlineValue = true;
    }
    if (spec.flags.count(name)) {
      if (inlineValue) throw UsageError("option " + name + " takes no value");
      parsed.flags.insert(name);
    } else if (spec.withValue.count(name)) {
      if (!inlineValue) {
        if (i + 1 >= args.size()) throw UsageError("option " + name + " needs a value");
        value = args[++i];
      }
      parsed.values[name] = value;
      parsed.allValues[name].push_back(value);
    } else {
      throw UsageError("unknown option " + name);
    }
  }
  return parsed;
}

std::pair<int, int> parseSize(const std::string& text) {
  int w = 0, h = 0;
  char x = 0, rest = 0;
  std::istringstream in(text);
  if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> rest) || w <= 0 || h <= 0 || w > 16384 ||
      h > 16384)
    throw UsageError("--size expects WIDTHxHEIGHT (e.g. 1024x768), got '" + text + "'");
  return {w, h};
}

std::vector<double> parseNumbers(const std::string& text, size_t count, const std::string& option) {
  std::vector<double> numbers;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    try {
      size_t used = 0;
      numbers.push_back(std::stod(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw UsageError(option + " expects " + std::to_string(count) + " comma-separated numbers, got '" +
                       text + "'");
    }
  }
  if (numbers.size() != count)
    throw UsageError(option + " expects " + std::to_string(count) + " comma-separated numbers, got '" + text +
                     "'");
  return numbers;
}

}  // namespace medial::cli
