// Running a command's filter: input set, progress line shown, errors turned into one Failure line.
#pragma once

#include "Progress.h"

#include <string>

class vtkAlgorithm;
class vtkDataObject;

namespace medial::cli {

// Updates `filter` on `data` (read from `inputName`) with a progress line labelled `label`; throws Failure
// "INPUT: the filter's errors" when it reports any, Cancelled when Ctrl-C stopped it.
void runFilter(vtkAlgorithm* filter, vtkDataObject* data, const std::string& inputName,
               const std::string& label, ProgressLine& progress);

}  // namespace medial::cli
