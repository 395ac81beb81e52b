// SliceViews: axial, coronal and sagittal views of one volume sharing a cursor (linked crosshair) and a
// window/level, with presets for CT (bone, soft tissue, lung/air) and the full range.
#pragma once

#include "SliceView.h"

#include <QWidget>

class QComboBox;
class QLabel;

namespace medial::gui {

class SliceViews : public QWidget {
  Q_OBJECT

 public:
  using Point = SliceView::Point;

  explicit SliceViews(QWidget* parent = nullptr);

  void setVolume(vtkImageData* volume, const QString& name);
  vtkImageData* volume() const { return volume_; }
  SliceView* view(int axis) const { return views_[axis]; }
  Point cursor() const { return cursor_; }
  void setCursor(const Point& cursor);
  double window() const { return window_; }
  double level() const { return level_; }
  void setWindowLevel(double window, double level);
  // Presets: 0 full range, 1 bone, 2 soft tissue, 3 lung/air.
  void applyPreset(int preset);

 signals:
  void cursorChanged(const Point& cursor);
  void pointClicked(const Point& point);  // a left click in a slice view (a seed)
  void windowLevelChanged(double window, double level);

 private:
  void updateLabel();

  SliceView* views_[3] = {};
  QComboBox* presets_ = nullptr;
  QLabel* label_ = nullptr;
  vtkSmartPointer<vtkImageData> volume_;
  QString name_;
  Point cursor_{0, 0, 0};
  double window_ = 1, level_ = 0;
  double range_[2] = {0, 1};
};

}  // namespace medial::gui
