#include "ReadInput.h"

#include "CommandLine.h"
#include "Progress.h"

#include "MedialErrorCollector.h"
#include "vtkMedialReader.h"

namespace medial::cli {

vtkSmartPointer<vtkDataObject> readInput(const std::string& path, ProgressLine& progress) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  auto errors = medial::ErrorCollector::Watch(reader);
  reader->SetFileName(path.c_str());
  progress.watch(reader, "reading " + path);
  reader->Update();
  progress.finish();
  if (errors->HasErrors())
    throw Failure(reader->GetErrorMessage()[0] ? reader->GetErrorMessage() : errors->Joined());
  return reader->GetOutputDataObject(0);
}

}  // namespace medial::cli
