#include "MedialTextFile.h"

#include <cstdlib>
#include <sstream>

namespace medial {

bool TextFile::open(const std::string& path, std::string& error) {
  path_ = path;
  line_ = 0;
  if (path.empty()) {
    error = "no file name given";
    return false;
  }
  in_.open(path);
  if (!in_) {
    error = path + ": cannot open the file";
    return false;
  }
  return true;
}

bool TextFile::nextLine(std::string& text) {
  if (!std::getline(in_, text)) return false;
  ++line_;
  const size_t hash = text.find('#');
  if (hash != std::string::npos) text.erase(hash);
  return true;
}

std::string TextFile::where() const { return path_ + ":" + std::to_string(line_) + ": "; }

bool parseNumbers(const std::string& text, std::vector<double>& numbers) {
  numbers.clear();
  std::istringstream fields(text);
  std::string field;
  while (fields >> field) {
    char* end = nullptr;
    const double value = std::strtod(field.c_str(), &end);
    if (end == field.c_str() || *end != '\0') return false;
    numbers.push_back(value);
  }
  return true;
}

bool isBlank(const std::string& text) { return text.find_first_not_of(" \t\r") == std::string::npos; }

}  // namespace medial
