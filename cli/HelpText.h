// Pieces of the commands' --help texts that take their content from a filter, so that they cannot drift.
#pragma once

#include <string>

namespace medial::cli {

// A help line for an option that takes one of a filter's names: "  OPTION   [lead ]a (default), b, c",
// wrapped under the description column. The names and the default are the filter's.
std::string namesHelp(const std::string& option, const std::string& lead, const std::string& names,
                      const std::string& defaultName);

// A default in the help, as short as it prints.
std::string number(double value);

}  // namespace medial::cli
