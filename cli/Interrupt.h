// Ctrl-C on the `medial` command: the first SIGINT (or SIGTERM) asks the running filter to stop at its next
// progress report (AbortExecute, filters/MedialProgress.h); the command then exits with kCancelled and
// writes no output. A second signal ends the process at once, as if none were caught.
#pragma once

class vtkAlgorithm;

namespace medial::cli {

// Installs the handlers; called once by main().
void catchInterrupts();
// True once a SIGINT or SIGTERM arrived.
bool interrupted();
// Sets `filter`'s AbortExecute at each of its progress reports once interrupted().
void abortOnInterrupt(vtkAlgorithm* filter);

}  // namespace medial::cli
