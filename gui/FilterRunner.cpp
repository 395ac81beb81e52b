#include "FilterRunner.h"

#include "MedialErrorCollector.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QThread>

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>

namespace medial::gui {

FilterRunner::FilterRunner(QObject* parent) : QObject(parent) {}

FilterRunner::~FilterRunner() {
  if (thread_) {
    cancel();
    thread_->wait();
  }
}

bool FilterRunner::start(vtkAlgorithm* filter, const QString& label) {
  if (thread_ || !filter) return false;
  filter_ = filter;
  label_ = label;
  cancelled_ = false;
  lastPercent_ = -1;
  error_.clear();
  filter->SetAbortExecute(0);

  thread_ = QThread::create([this] {
    auto errors = medial::ErrorCollector::Watch(filter_);
    // Progress comes on this thread: forward whole percents only, queued to the UI thread.
    auto progress = vtkSmartPointer<vtkCallbackCommand>::New();
    progress->SetClientData(this);
    progress->SetCallback([](vtkObject* caller, unsigned long, void* self, void* fraction) {
      auto* runner = static_cast<FilterRunner*>(self);
      // The abort flag is set here, on the worker thread: setting it from the UI thread would call
      // Modified() and invoke observers while this thread adds, calls and removes its own.
      if (runner->cancelled_) static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
      const int percent = static_cast<int>(*static_cast<double*>(fraction) * 100.0);
      if (runner->lastPercent_.exchange(percent) != percent) emit runner->progressed(percent);
    });
    const unsigned long tag = filter_->AddObserver(vtkCommand::ProgressEvent, progress);
    QElapsedTimer timer;
    timer.start();
    filter_->Update();
    seconds_ = timer.nsecsElapsed() * 1e-9;
    filter_->RemoveObserver(tag);
    filter_->RemoveObserver(errors);
    if (cancelled_)
      error_ = "cancelled";
    else if (errors->HasErrors())
      error_ = QString::fromStdString(errors->Joined());
  });
  connect(thread_, &QThread::finished, this, &FilterRunner::onThreadFinished);
  thread_->start();
  return true;
}

void FilterRunner::cancel() {
  if (!thread_) return;
  cancelled_ = true;  // the worker sets the filter's AbortExecute at its next progress report
}

void FilterRunner::wait() {
  while (thread_) {
    if (thread_->wait(20)) QCoreApplication::processEvents();  // delivers finished() and onThreadFinished
    QCoreApplication::processEvents();
  }
}

void FilterRunner::onThreadFinished() {
  thread_->deleteLater();
  thread_ = nullptr;
  vtkSmartPointer<vtkAlgorithm> filter = filter_;
  filter_ = nullptr;
  emit finished(filter, error_.isEmpty(), error_, seconds_);
}

}  // namespace medial::gui
