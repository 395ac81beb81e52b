#include "FilterPanel.h"

#include "NodeColors.h"
#include "ObjectList.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkPointData.h>

#include <algorithm>

namespace medial::gui {

FilterPanel::FilterPanel(const QString& title, SceneObject::Kind inputKind, std::vector<Parameter> parameters,
                         ObjectList* objects, QWidget* parent)
    : QWidget(parent), title_(title), inputKind_(inputKind), objects_(objects) {
  setObjectName(title);
  inputs_ = new QComboBox(this);
  inputs_->setObjectName("input");
  inputs_->setToolTip("The " + kindName(inputKind) + " the filter runs on");
  form_ = new ParameterForm(std::move(parameters), this);
  run_ = new QPushButton("Run", this);
  run_->setObjectName("run");
  cancel_ = new QPushButton("Cancel", this);
  cancel_->setObjectName("cancel");
  cancel_->setEnabled(false);
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 100);
  progress_->setValue(0);

  auto* inputRow = new QFormLayout;
  inputRow->addRow("Input " + kindName(inputKind), inputs_);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(run_);
  buttons->addWidget(cancel_);
  extra_ = new QVBoxLayout;
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(inputRow);
  layout->addWidget(form_);
  layout->addLayout(buttons);
  layout->addWidget(progress_);
  layout->addLayout(extra_);
  layout->addStretch(1);

  connect(run_, &QPushButton::clicked, this, [this] { run(); });
  connect(cancel_, &QPushButton::clicked, this, &FilterPanel::cancel);
  connect(&runner_, &FilterRunner::progressed, progress_, &QProgressBar::setValue);
  connect(&runner_, &FilterRunner::finished, this, &FilterPanel::onFinished);
  connect(inputs_, &QComboBox::currentIndexChanged, this, [this] {
    if (SceneObject* object = input()) inputChanged(object);
  });
  connect(objects_, &ObjectList::objectsChanged, this, &FilterPanel::refreshInputs);
  connect(objects_, &ObjectList::currentChanged, this, [this](SceneObject* object) {
    if (object && object->kind == inputKind_ && !isRunning()) setInput(object);
  });
  refreshInputs();
}

void FilterPanel::refreshInputs() {
  SceneObject* selected = input();
  const QSignalBlocker block(inputs_);
  inputs_->clear();
  for (SceneObject* object : objects_->ofKind(inputKind_))
    inputs_->addItem(object->name, QVariant::fromValue(static_cast<void*>(object)));
  if (selected) setInput(selected);
  if (input() != selected && input()) inputChanged(input());  // signals were blocked
  run_->setEnabled(inputs_->count() > 0 && !isRunning());
}

SceneObject* FilterPanel::input() const {
  if (inputs_->currentIndex() < 0) return nullptr;
  auto* object = static_cast<SceneObject*>(inputs_->currentData().value<void*>());
  // The combo may name an object deleted since: trust only live ones.
  for (SceneObject* live : objects_->ofKind(inputKind_))
    if (live == object) return object;
  return nullptr;
}

void FilterPanel::setInput(SceneObject* object) {
  const int index = inputs_->findData(QVariant::fromValue(static_cast<void*>(object)));
  if (index >= 0) inputs_->setCurrentIndex(index);
}

vtkSmartPointer<vtkDataObject> FilterPanel::copyOf(SceneObject* object) {
  vtkSmartPointer<vtkDataObject> copy = vtkSmartPointer<vtkDataObject>::Take(object->data->NewInstance());
  copy->ShallowCopy(object->data);
  return copy;
}

void FilterPanel::runAgain() {
  if (!isRunning()) {
    run();
    return;
  }
  runAgainPending_ = true;
  runner_.cancel();
}

bool FilterPanel::run() {
  if (isRunning()) return false;
  SceneObject* object = input();
  if (!object) {
    emit failed(title_, "Open or compute a " + kindName(inputKind_) + " first.");
    return false;
  }
  QString error;
  vtkSmartPointer<vtkAlgorithm> filter = makeFilter(object, error);
  if (!filter) {
    emit failed(title_, error);
    return false;
  }
  runningInput_ = object;
  progress_->setValue(0);
  run_->setEnabled(false);
  cancel_->setEnabled(true);
  emit message(title_ + ": running on " + object->name);
  runner_.start(filter, title_);
  return true;
}

void FilterPanel::onFinished(vtkAlgorithm* filter, bool ok, const QString& text, double seconds) {
  run_->setEnabled(inputs_->count() > 0);
  cancel_->setEnabled(false);
  progress_->setValue(ok ? 100 : 0);
  SceneObject* object = runningInput_;
  runningInput_ = nullptr;
  bool live = false;
  for (SceneObject* candidate : objects_->ofKind(inputKind_)) live = live || candidate == object;
  lastOk_ = ok && live;
  if (ok && live) {
    collect(filter, object, seconds);
    if (record_ && record_->isChecked()) {
      recorded_ = steps(filter);
      stepsInput_ = object->name;
      const QSignalBlocker block(stepSlider_);
      stepSlider_->setRange(0, std::max(0, stepCount() - 1));
      stepSlider_->setValue(0);
      stepSlider_->setEnabled(stepCount() > 0);
      stepLabel_->setText(stepCount() > 0 ? QString("%1 steps").arg(stepCount()) : QString("no steps"));
    }
    emit message(QString("%1: done in %2 s").arg(title_).arg(seconds, 0, 'f', 2));
  } else if (text == "cancelled") {
    emit message(title_ + ": cancelled");
  } else {
    const QString why = ok ? QString("the input was deleted during the run") : text;
    emit message(title_ + ": failed: " + why);
    emit failed(title_ + " failed", why);
  }
  emit completed(lastOk_);
  if (runAgainPending_) {
    runAgainPending_ = false;
    run();
  }
}

void FilterPanel::enableSteps(const QString& tooltip) {
  record_ = new QCheckBox("Record steps", this);
  record_->setObjectName("recordSteps");
  record_->setToolTip(tooltip);
  stepSlider_ = new QSlider(Qt::Horizontal, this);
  stepSlider_->setObjectName("steps");
  stepSlider_->setEnabled(false);
  stepSlider_->setPageStep(1);
  stepLabel_ = new QLabel("Run with \"Record steps\" on", this);
  stepLabel_->setWordWrap(true);
  auto* rows = new QFormLayout;
  rows->addRow(record_);
  rows->addRow("Show step", stepSlider_);
  rows->addRow(stepLabel_);
  extra_->addLayout(rows);
  connect(stepSlider_, &QSlider::valueChanged, this, [this](int index) { showStep(index); });
}

bool FilterPanel::recordSteps() const { return record_ && record_->isChecked(); }

void FilterPanel::setRecordSteps(bool on) {
  if (record_) record_->setChecked(on);
}

QString FilterPanel::stepName(int index) const {
  return index >= 0 && index < stepCount() ? recorded_[size_t(index)].first : QString();
}

bool FilterPanel::showStep(int index) {
  if (index < 0 || index >= stepCount()) return false;
  const QString name = stepsInput_ + " step";
  if (SceneObject* previous = objects_->findByName(name)) objects_->remove(previous);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->ShallowCopy(recorded_[size_t(index)].second);
  SceneObject* shown = objects_->add(name, data, QString(), kComputedRadiusScale);
  // A stage labelled per point (SQM's polyhedra by node, the TSK voxels by cluster) in a color per label.
  for (const char* label : {"SkeletonNode", "Cluster"})
    if (vtkDataArray* ids = data->GetPointData()->GetArray(label);
        ids && shown && data->GetNumberOfPolys() + data->GetNumberOfVerts() > 0) {
      colorByLabel(vtkActor::SafeDownCast(shown->prop), label, int(ids->GetRange()[1]) + 1);
      break;
    }
  stepLabel_->setText(QString("%1 of %2: %3").arg(index + 1).arg(stepCount()).arg(stepName(index)));
  if (stepSlider_->value() != index) {
    const QSignalBlocker block(stepSlider_);
    stepSlider_->setValue(index);
  }
  return shown != nullptr;
}

}  // namespace medial::gui
