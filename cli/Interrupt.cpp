#include "Interrupt.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkSmartPointer.h>

#include <csignal>

namespace medial::cli {
namespace {

volatile std::sig_atomic_t signalled = 0;

extern "C" void onSignal(int number) {
  signalled = 1;
  std::signal(number, SIG_DFL);  // a second Ctrl-C is not caught
}

}  // namespace

void catchInterrupts() {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
}

bool interrupted() { return signalled != 0; }

InterruptScope::InterruptScope(vtkAlgorithm* filter) : filter_(filter) {
  auto callback = vtkSmartPointer<vtkCallbackCommand>::New();
  callback->SetCallback([](vtkObject* caller, unsigned long, void*, void*) {
    if (interrupted()) static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
  });
  observer_ = filter->AddObserver(vtkCommand::ProgressEvent, callback);
}

InterruptScope::~InterruptScope() { filter_->RemoveObserver(observer_); }

}  // namespace medial::cli
