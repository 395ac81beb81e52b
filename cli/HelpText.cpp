#include "HelpText.h"

#include <sstream>

namespace medial::cli {

// A help line for an option that takes one of a filter's names: "  OPTION   [lead ]a (default), b, c",
// wrapped under the description column. The names and the default are the filter's.
std::string namesHelp(const std::string& option, const std::string& lead, const std::string& names,
                      const std::string& defaultName) {
  const std::string column(28, ' ');
  std::string text = "  " + option + std::string(26 - option.size(), ' ') + lead, line;
  size_t start = 0;
  while (start <= names.size()) {
    size_t comma = names.find(',', start);
    if (comma == std::string::npos) comma = names.size();
    std::string name = names.substr(start, comma - start);
    name.erase(0, name.find_first_not_of(' '));
    std::string item = name + (name == defaultName ? " (default)" : "") + (comma < names.size() ? "," : "");
    if (text.size() + 1 + item.size() > 100) {
      line += text + "\n";
      text = column;
    } else if (text.back() != ' ') {
      text += ' ';
    }
    text += item;
    start = comma + 1;
  }
  return line + text + "\n";
}

// A default in the help, as short as it prints.
std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace medial::cli
