#include "MedialProgress.h"

#include <vtkAlgorithm.h>
#include <vtkSetGet.h>

namespace medial {

std::function<bool(double)> progressOf(vtkAlgorithm* filter) {
  return [filter](double fraction) {
    filter->UpdateProgress(fraction);
    return !filter->GetAbortExecute();
  };
}

void reportError(vtkAlgorithm* filter, const Error& error) {
  if (error.empty()) return;
  if (error.isCancelled()) filter->SetAbortExecute(1);
  vtkErrorWithObjectMacro(filter, << error.message());
}

}  // namespace medial
