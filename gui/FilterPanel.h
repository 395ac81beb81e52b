// FilterPanel: the common part of every filter's panel: the input (an object of the right kind), the
// parameter form, Run and Cancel, and a progress bar. The filter runs on a worker thread (FilterRunner);
// a subclass says how to build the filter from the form and what to do with its outputs.
#pragma once

#include "FilterRunner.h"
#include "ParameterForm.h"
#include "SceneObject.h"

#include <QWidget>

#include <vtkAlgorithm.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <utility>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;
class QProgressBar;
class QPushButton;
class QVBoxLayout;

namespace medial::gui {

class ObjectList;

class FilterPanel : public QWidget {
  Q_OBJECT

 public:
  FilterPanel(const QString& title, SceneObject::Kind inputKind, std::vector<Parameter> parameters,
              ObjectList* objects, QWidget* parent = nullptr);

  QString title() const { return title_; }
  ParameterForm* form() const { return form_; }
  SceneObject* input() const;
  void setInput(SceneObject* object);
  // Starts the filter on the selected input; false (with an error) when there is none or one is running.
  bool run();
  // Stops the run under way (and a pending runAgain).
  void cancel() {
    runAgainPending_ = false;
    runner_.cancel();
  }
  bool isRunning() const { return runner_.isRunning(); }
  // Runs now, or, when a run is under way, cancels it and runs again once it has stopped (live updates).
  void runAgain();
  void wait() { runner_.wait(); }
  // Whether the last run ended well (false before any run).
  bool lastRunSucceeded() const { return lastOk_; }
  // "Show steps": the intermediate results of the last run (the papers' figures) when "Record steps" was
  // on; showStep puts one in the scene as "<input> step" (false out of range).
  int stepCount() const { return int(recorded_.size()); }
  QString stepName(int index) const;
  bool showStep(int index);
  void setRecordSteps(bool on);
  // The filter run() would start on `input`, with the form's values (null when the panel refuses it).
  vtkSmartPointer<vtkAlgorithm> configuredFilter(SceneObject* input) {
    QString error;
    return makeFilter(input, error);
  }

 signals:
  void message(const QString& text);  // a line for the log
  void failed(const QString& title, const QString& message);
  void completed(bool ok);

 protected:
  // The filter for `input` with the form's values, its input data set (a shallow copy); null + error to stop.
  virtual vtkSmartPointer<vtkAlgorithm> makeFilter(SceneObject* input, QString& error) = 0;
  // Puts the outputs of a successful run into the object list.
  virtual void collect(vtkAlgorithm* filter, SceneObject* input, double seconds) = 0;
  // Called when another input is selected (e.g. to suggest parameter values that suit it).
  virtual void inputChanged(SceneObject* /*input*/) {}
  // A panel whose filter records its steps calls this once: it adds the "Show steps" controls.
  void enableSteps(const QString& tooltip);
  // Whether the next run records its steps (for makeFilter).
  bool recordSteps() const;
  // The recorded steps of a successful run, in order (name, data).
  using Steps = std::vector<std::pair<QString, vtkSmartPointer<vtkPolyData>>>;
  virtual Steps steps(vtkAlgorithm* /*filter*/) { return {}; }
  // Extra controls go below the Run/Cancel row.
  QVBoxLayout* extraLayout() const { return extra_; }
  ObjectList* objects() const { return objects_; }
  // A copy of the object's data the worker thread may read while the UI keeps rendering the original.
  static vtkSmartPointer<vtkDataObject> copyOf(SceneObject* object);

 private:
  void refreshInputs();
  void onFinished(vtkAlgorithm* filter, bool ok, const QString& message, double seconds);

  QString title_;
  SceneObject::Kind inputKind_;
  ObjectList* objects_;
  ParameterForm* form_ = nullptr;
  QComboBox* inputs_ = nullptr;
  QPushButton* run_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QVBoxLayout* extra_ = nullptr;
  FilterRunner runner_;
  SceneObject* runningInput_ = nullptr;
  bool runAgainPending_ = false;
  bool lastOk_ = false;
  QCheckBox* record_ = nullptr;
  QSlider* stepSlider_ = nullptr;
  QLabel* stepLabel_ = nullptr;
  Steps recorded_;
  QString stepsInput_;  // the input the recorded steps belong to
};

}  // namespace medial::gui
