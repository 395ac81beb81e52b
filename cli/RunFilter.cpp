#include "RunFilter.h"

#include "CommandLine.h"
#include "Interrupt.h"

#include "MedialErrorCollector.h"

#include <vtkAlgorithm.h>
#include <vtkDataObject.h>

namespace medial::cli {

void runFilter(vtkAlgorithm* filter, vtkDataObject* data, const std::string& inputName,
               const std::string& label, ProgressLine& progress) {
  auto errors = medial::ErrorCollector::Watch(filter);
  filter->SetInputDataObject(data);
  if (interrupted()) throw Cancelled();  // Ctrl-C while the input was read
  progress.watch(filter, label);
  {
    const InterruptScope interrupts(filter);
    filter->Update();
    progress.finish();
    // Also a signal after the filter's last progress report: the user asked for nothing to be written.
    if (filter->GetAbortExecute() || interrupted()) throw Cancelled();
  }
  if (errors->HasErrors()) throw Failure(inputName + ": " + errors->Joined());
}

}  // namespace medial::cli
