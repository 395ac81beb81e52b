#include "SliceViews.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <algorithm>

namespace medial::gui {

SliceViews::SliceViews(QWidget* parent) : QWidget(parent) {
  presets_ = new QComboBox(this);
  presets_->setObjectName("windowLevelPreset");
  presets_->addItems(
      {"Full range", "Bone (W 1800, L 400)", "Soft tissue (W 400, L 40)", "Lung / air (W 1500, L -600)"});
  presets_->setToolTip("Window/level presets (Hounsfield units); right-drag in a slice view adjusts them");
  label_ = new QLabel(this);
  label_->setObjectName("cursorLabel");
  auto* top = new QHBoxLayout;
  top->addWidget(new QLabel("Window/level", this));
  top->addWidget(presets_);
  top->addWidget(label_, 1);

  auto* row = new QHBoxLayout;
  const char* names[3] = {"sagittal", "coronal", "axial"};
  for (int axis : {2, 1, 0}) {
    views_[axis] = new SliceView(axis, this);
    views_[axis]->setObjectName(names[axis]);
    views_[axis]->setToolTip(QString(names[axis]) +
                             ": click to move the crosshair (and pick a seed), wheel for "
                             "slices, right-drag for window/level, middle-drag to pan, Ctrl+wheel to zoom");
    row->addWidget(views_[axis]);
    connect(views_[axis], &SliceView::cursorPicked, this, [this](const Point& p) {
      setCursor(p);
      emit pointClicked(p);
    });
    connect(views_[axis], &SliceView::windowLevelDragged, this, &SliceViews::setWindowLevel);
    connect(views_[axis], &SliceView::sliceStepped, this, [this, axis](int steps) {
      if (!volume_) return;
      Point p = cursor_;
      p[axis] += steps * volume_->GetSpacing()[axis];
      double bounds[6];
      volume_->GetBounds(bounds);
      p[axis] = std::clamp(p[axis], bounds[2 * axis], bounds[2 * axis + 1]);
      setCursor(p);
    });
  }
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(top);
  layout->addLayout(row, 1);
  connect(presets_, &QComboBox::currentIndexChanged, this, &SliceViews::applyPreset);
}

void SliceViews::setVolume(vtkImageData* volume, const QString& name) {
  volume_ = volume;
  name_ = name;
  for (SliceView* view : views_) view->setVolume(volume);
  if (!volume) return;
  volume->GetPointData()->GetScalars()->GetRange(range_, 0);
  double center[3];
  volume->GetCenter(center);
  setCursor({center[0], center[1], center[2]});
  // CT data (values below -500 HU) opens in the soft-tissue window, anything else in its full range.
  const int preset = range_[0] < -500 ? 2 : 0;
  if (presets_->currentIndex() == preset)
    applyPreset(preset);
  else
    presets_->setCurrentIndex(preset);
}

void SliceViews::setCursor(const Point& cursor) {
  cursor_ = cursor;
  for (SliceView* view : views_) view->setCursor(cursor);
  updateLabel();
  emit cursorChanged(cursor);
}

void SliceViews::setWindowLevel(double window, double level) {
  window_ = window;
  level_ = level;
  for (SliceView* view : views_) view->setWindowLevel(window, level);
  updateLabel();
  emit windowLevelChanged(window, level);
}

void SliceViews::applyPreset(int preset) {
  switch (preset) {
    case 1:
      setWindowLevel(1800, 400);
      break;
    case 2:
      setWindowLevel(400, 40);
      break;
    case 3:
      setWindowLevel(1500, -600);
      break;
    default:
      setWindowLevel(std::max(range_[1] - range_[0], 1e-6), 0.5 * (range_[0] + range_[1]));
      break;
  }
}

void SliceViews::updateLabel() {
  if (!volume_) {
    label_->clear();
    return;
  }
  int ijk[3];
  double pcoords[3];
  double x[3] = {cursor_[0], cursor_[1], cursor_[2]};
  QString value;
  if (volume_->ComputeStructuredCoordinates(x, ijk, pcoords))
    value = QString::number(volume_->GetScalarComponentAsDouble(
        views_[0]->sliceIndex(), views_[1]->sliceIndex(), views_[2]->sliceIndex(), 0));
  label_->setText(QString("%1  (%2, %3, %4) mm  value %5  W %6 L %7")
                      .arg(name_)
                      .arg(cursor_[0], 0, 'f', 1)
                      .arg(cursor_[1], 0, 'f', 1)
                      .arg(cursor_[2], 0, 'f', 1)
                      .arg(value.isEmpty() ? QString("-") : value)
                      .arg(window_, 0, 'g', 4)
                      .arg(level_, 0, 'g', 4));
}

}  // namespace medial::gui
