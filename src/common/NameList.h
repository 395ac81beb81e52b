/// \file
/// NameList: a list of option names (solvers, smoothing schemes, pairings) joined for messages and help.
#pragma once

#include <string>
#include <vector>

namespace medial {

/// The names joined by `separator`: "a, b, c".
inline std::string joinNames(const std::vector<std::string>& names, const std::string& separator = ", ") {
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : separator) + name;
  return joined;
}

}  // namespace medial
