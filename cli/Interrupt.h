// Ctrl-C on the `medial` commands that run a filter: the first SIGINT (or SIGTERM) is remembered; the
// running filter stops at its next progress report (AbortExecute, filters/MedialProgress.h), or the
// filter does not start, and the command exits with kCancelled writing no output. A second signal ends
// the process at once. `medial render` runs no filter and keeps the signals' default handling.
#pragma once

class vtkAlgorithm;

namespace medial::cli {

// Installs the handlers (main(), for the commands that run a filter).
void catchInterrupts();
// True once a SIGINT or SIGTERM arrived.
bool interrupted();

// While it lives, sets `filter`'s AbortExecute at each of its progress reports once interrupted().
class InterruptScope {
 public:
  explicit InterruptScope(vtkAlgorithm* filter);
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  vtkAlgorithm* filter_;
  unsigned long observer_;
};

}  // namespace medial::cli
