#include "FilterOptions.h"

#include "MedialErrorCollector.h"

#include <vtkObject.h>

#include <cmath>
#include <sstream>

namespace medial::cli {

namespace {

std::string rangeText(double minimum, double maximum, bool whole) {
  std::ostringstream text;
  text << (whole ? "a whole number " : "a number ");
  // The widest ranges stand for "no upper bound": the type's limit is no help to the user.
  if (maximum >= 2147483647.0)
    text << ">= " << minimum;
  else
    text << "in " << minimum << ".." << maximum;
  return text.str();
}

}  // namespace

void setNumberFromOption(const ParsedArgs& parsed, const std::string& option, double minimum, double maximum,
                         bool whole, const std::function<void(double)>& set) {
  if (!parsed.has(option)) return;
  const double value = parseNumbers(parsed.value(option), 1, option)[0];
  if (!(value >= minimum && value <= maximum) || (whole && value != std::floor(value)))
    throw UsageError(option + " must be " + rangeText(minimum, maximum, whole) + ", got '" +
                     parsed.value(option) + "'");
  set(value);
}

void setNameFromOption(const ParsedArgs& parsed, const std::string& option, vtkObject* filter,
                       const std::function<void(const std::string&)>& set) {
  if (!parsed.has(option)) return;
  auto errors = medial::ErrorCollector::Watch(filter);
  set(parsed.value(option));
  if (errors->HasErrors()) throw UsageError(option + ": " + errors->Joined());
}

}  // namespace medial::cli
