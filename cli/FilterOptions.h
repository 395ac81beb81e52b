// Filter properties from command-line options. A property is set only when its option is given (the
// filter's default stands otherwise), and the value is checked against the range the filter itself
// declares (its vtkSetClampMacro's Get<Property>MinValue/MaxValue): out of range is a usage error naming
// the option and the range. The filter is the one place that knows a parameter's default and range
// (docs/ARCHITECTURE.md §3).
#pragma once

#include "CommandLine.h"

#include <functional>
#include <string>
#include <type_traits>

class vtkObject;

namespace medial::cli {

// When `option` is given: its number, checked to lie in [minimum, maximum] (and to be whole when `whole`),
// is passed to `set`. Throws UsageError.
void setNumberFromOption(const ParsedArgs& parsed, const std::string& option, double minimum, double maximum,
                         bool whole, const std::function<void(double)>& set);

// When `option` is given: `set(name)`; an error the filter reports for the name becomes a usage error.
void setNameFromOption(const ParsedArgs& parsed, const std::string& option, vtkObject* filter,
                       const std::function<void(const std::string&)>& set);

}  // namespace medial::cli

// MEDIAL_OPTION(parsed, "--nodes", filter, TargetNodes): filter->SetTargetNodes(N) when --nodes N is given,
// N checked against the filter's range for TargetNodes.
#define MEDIAL_OPTION(parsed, option, filter, Property)                                                     \
  ::medial::cli::setNumberFromOption(                                                                       \
      parsed, option, double((filter)->Get##Property##MinValue()),                                          \
      double((filter)->Get##Property##MaxValue()), std::is_integral_v<decltype((filter)->Get##Property())>, \
      [&](double value) {                                                                                   \
        (filter)->Set##Property(static_cast<decltype((filter)->Get##Property())>(value));                   \
      })
