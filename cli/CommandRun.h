// What every command does around its filter, once: the progress line (--quiet), the stage times
// (--timings), reading its inputs, the folder of the papers' intermediate results, and printing the times
// at the end.
#pragma once

#include "CommandLine.h"
#include "Progress.h"
#include "Timings.h"
#include "WriteOutput.h"

#include <vtkDataObject.h>
#include <vtkSmartPointer.h>

#include <string>

class vtkAlgorithm;
class vtkPolyData;

namespace medial::cli {

class CommandRun {
 public:
  explicit CommandRun(const ParsedArgs& parsed);

  ProgressLine& progress() { return progress_; }
  Timings& timings() { return timings_; }

  // Reads `path` (stage "read"); a read error is a Failure naming the file.
  vtkSmartPointer<vtkDataObject> read(const std::string& path);
  // Reads `path` and requires a surface mesh: a Failure "PATH: not a surface mesh (no polygons)" else.
  vtkSmartPointer<vtkPolyData> readSurface(const std::string& path);
  // The folder given to `option` (made, or a usage error), with the filter's RecordStages on; "" when
  // the option is not given.
  template <class Filter>
  std::string stagesFolder(Filter* filter, const char* option = "--stages") {
    if (!parsed_.has(option)) return "";
    const std::string folder = parsed_.value(option);
    makeOutputDirectory(folder, option);
    filter->RecordStagesOn();
    return folder;
  }
  // Runs `filter` on `data` as stage `stage`, with a progress line labelled `label` (RunFilter.h).
  void run(vtkAlgorithm* filter, vtkDataObject* data, const std::string& inputName, const std::string& stage,
           const std::string& label);
  // Ends the last stage and prints the times with --timings; returns kSuccess.
  int finish();

 private:
  const ParsedArgs& parsed_;
  ProgressLine progress_;
  Timings timings_;
};

}  // namespace medial::cli
