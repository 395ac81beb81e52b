#include "RunFilter.h"

#include "CommandLine.h"

#include "MedialErrorCollector.h"

#include <vtkAlgorithm.h>
#include <vtkDataObject.h>

namespace medial::cli {

void runFilter(vtkAlgorithm* filter, vtkDataObject* data, const std::string& inputName,
               const std::string& label, ProgressLine& progress) {
  auto errors = medial::ErrorCollector::Watch(filter);
  filter->SetInputDataObject(data);
  progress.watch(filter, label);
  filter->Update();
  progress.finish();
  if (errors->HasErrors()) throw Failure(inputName + ": " + errors->Joined());
}

}  // namespace medial::cli
