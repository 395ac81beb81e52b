// Progress line of the `medial` command: "label  42%" redrawn on stderr when it is a terminal and
// --quiet was not given (docs/ARCHITECTURE.md §6). Observes a VTK algorithm's ProgressEvent.
// With the environment variable MEDIAL_PROGRESS=lines (for programs running `medial`, such as the
// Blender add-on) it is one line "medial-progress LABEL PERCENT" per change instead, on a pipe too.
#pragma once

#include <string>

class vtkAlgorithm;

namespace medial::cli {

class ProgressLine {
 public:
  explicit ProgressLine(bool quiet);
  ~ProgressLine();

  // Shows progress of `algorithm` under `label` until the next watch() or finish().
  void watch(vtkAlgorithm* algorithm, const std::string& label);
  void show(const std::string& label, double fraction);
  // Clears the line.
  void finish();

 private:
  bool enabled_;
  bool asLines_;
  bool drawn_ = false;
  int lastPercent_ = -1;
};

}  // namespace medial::cli
