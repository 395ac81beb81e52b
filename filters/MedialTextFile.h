/// \file
/// The text input of the readers that Medial parses itself (SWC, sketch .txt, the OFF header): the file
/// opened with a clear error, read line by line with its line numbers and '#' comments stripped, and
/// fields parsed as numbers strictly (a field that is not wholly a number is an error, not a zero).
#pragma once

#include <fstream>
#include <string>
#include <vector>

namespace medial {

/// A text file read line by line, comments removed, with "PATH:LINE: " for messages.
class TextFile {
 public:
  /// Opens `path`; false with the reason ("no file name given", "PATH: cannot open the file").
  bool open(const std::string& path, std::string& error);
  /// The next line, its comment ('#' to the end) removed; false at the end of the file.
  bool nextLine(std::string& text);
  /// The number of the line nextLine gave last (from 1).
  int lineNumber() const { return line_; }
  /// "PATH:LINE: ", the start of a message about that line.
  std::string where() const;

 private:
  std::ifstream in_;
  std::string path_;
  int line_ = 0;
};

/// The whitespace-separated fields of `text` as numbers; false when a field is not wholly a number.
/// "nan" and "inf" are numbers, so that the data's validation can name the bad value.
bool parseNumbers(const std::string& text, std::vector<double>& numbers);

/// True when `text` holds only blanks (spaces, tabs, carriage returns).
bool isBlank(const std::string& text);

}  // namespace medial
