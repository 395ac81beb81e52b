// Reading one INPUT file of a `medial` command through vtkMedialReader, with a progress line; a read
// error becomes a Failure naming the file.
#pragma once

#include <vtkDataObject.h>
#include <vtkSmartPointer.h>

#include <string>

namespace medial::cli {

class ProgressLine;

vtkSmartPointer<vtkDataObject> readInput(const std::string& path, ProgressLine& progress);

}  // namespace medial::cli
