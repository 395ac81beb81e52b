// FilterRunner: updates a VTK filter on a worker thread so the window stays responsive. Progress events
// (fired on the worker) reach the UI thread as queued signals; cancel() makes the worker set the filter's
// AbortExecute at its next progress report, which our filters poll between stages and iterations.
#pragma once

#include <QObject>
#include <QString>

#include <vtkSmartPointer.h>

#include <atomic>

class QThread;
class vtkAlgorithm;

namespace medial::gui {

class FilterRunner : public QObject {
  Q_OBJECT

 public:
  explicit FilterRunner(QObject* parent = nullptr);
  ~FilterRunner() override;  // waits for a running filter (after asking it to abort)

  // Starts updating `filter` (its inputs already set, as copies the UI thread will not modify). Returns
  // false when another run is under way.
  bool start(vtkAlgorithm* filter, const QString& label);
  void cancel();
  bool isRunning() const { return thread_ != nullptr; }
  // Blocks until the current run has finished and its signal was delivered (tests, shutdown).
  void wait();

 signals:
  void progressed(int percent);
  // ok: the filter produced its outputs without errors. message: its errors joined, "cancelled", or empty.
  void finished(vtkAlgorithm* filter, bool ok, const QString& message, double seconds);

 private:
  void onThreadFinished();

  QThread* thread_ = nullptr;
  vtkSmartPointer<vtkAlgorithm> filter_;
  QString label_;
  std::atomic<bool> cancelled_{false};
  std::atomic<int> lastPercent_{-1};
  QString error_;
  double seconds_ = 0;
};

}  // namespace medial::gui
