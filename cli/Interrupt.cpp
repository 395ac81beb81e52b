#include "Interrupt.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkSmartPointer.h>

namespace medial::cli {
namespace {

volatile std::sig_atomic_t signalled = 0;

extern "C" void onSignal(int number) {
  signalled = 1;
  std::signal(number, SIG_DFL);  // a second Ctrl-C is not caught
}

}  // namespace

InterruptScope::InterruptScope(vtkAlgorithm* filter) : filter_(filter) {
  signalled = 0;
  previousInt_ = std::signal(SIGINT, onSignal);
  previousTerm_ = std::signal(SIGTERM, onSignal);
  auto callback = vtkSmartPointer<vtkCallbackCommand>::New();
  callback->SetCallback([](vtkObject* caller, unsigned long, void*, void*) {
    if (signalled) static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
  });
  observer_ = filter->AddObserver(vtkCommand::ProgressEvent, callback);
}

InterruptScope::~InterruptScope() {
  filter_->RemoveObserver(observer_);
  std::signal(SIGINT, previousInt_ == SIG_ERR ? SIG_DFL : previousInt_);
  std::signal(SIGTERM, previousTerm_ == SIG_ERR ? SIG_DFL : previousTerm_);
}

bool InterruptScope::interrupted() const { return signalled != 0; }

}  // namespace medial::cli
