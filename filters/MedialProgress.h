/// \file
/// MedialProgress: the one place where the progress and cancellation of src/'s algorithms meet VTK's. An
/// algorithm takes a callback that it calls with the fraction done and that returns false to stop it; its
/// result's Error is then a cancellation (src/common/Error.h). For a filter the callback forwards the
/// fraction to UpdateProgress and returns false once the filter's AbortExecute is set: by the GUI's Cancel,
/// the CLI's Ctrl-C, or any observer of ProgressEvent.
#pragma once

#include "common/Error.h"

#include <functional>

class vtkAlgorithm;

namespace medial {

/// The progress callback of `filter` for an algorithm of src/.
std::function<bool(double)> progressOf(vtkAlgorithm* filter);

/// Reports `error` as `filter`'s error (vtkErrorMacro: one line, an ErrorEvent). A cancellation is
/// reported as "cancelled" with the filter's AbortExecute left set, which is how callers tell it from a
/// failure.
void reportError(vtkAlgorithm* filter, const Error& error);

}  // namespace medial
