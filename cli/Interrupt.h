// Ctrl-C on the `medial` command while a filter runs: the first SIGINT (or SIGTERM) asks the filter to
// stop at its next progress report (AbortExecute, filters/MedialProgress.h); the command then exits with
// kCancelled and writes no output. A second signal ends the process at once, as does any signal outside a
// filter's run (reading, writing, rendering), as if none were caught.
#pragma once

#include <csignal>

class vtkAlgorithm;

namespace medial::cli {

// Catches SIGINT and SIGTERM while it lives, and sets `filter`'s AbortExecute at each of its progress
// reports once one came; the signals' previous handling is restored at the end.
class InterruptScope {
 public:
  explicit InterruptScope(vtkAlgorithm* filter);
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  // True once a SIGINT or SIGTERM arrived in this scope.
  bool interrupted() const;

 private:
  vtkAlgorithm* filter_;
  unsigned long observer_;
  void (*previousInt_)(int);
  void (*previousTerm_)(int);
};

}  // namespace medial::cli
