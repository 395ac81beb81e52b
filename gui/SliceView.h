// SliceView: one 2-D view of a volume along an axis (axial, coronal, sagittal) with a crosshair at the
// shared cursor and the patient's directions at the edges (R/L, A/P, S/I, for ITK's LPS frame). Left click or
// drag moves the cursor (and picks a seed); right drag changes window and level; the wheel steps through
// slices; middle drag pans and Ctrl+wheel zooms.
#pragma once

#include "VtkView.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <array>

class vtkActor;
class vtkImageData;
class vtkImageSlice;
class vtkImageSliceMapper;
class vtkPolyData;
class vtkRenderer;
class vtkTextActor;

namespace medial::gui {

class SliceView : public VtkView {
  Q_OBJECT

 public:
  using Point = std::array<double, 3>;

  // axis 2: axial (normal z), 1: coronal (normal y), 0: sagittal (normal x).
  SliceView(int axis, QWidget* parent = nullptr);
  ~SliceView() override;

  int axis() const { return axis_; }
  void setVolume(vtkImageData* volume);
  void setCursor(const Point& cursor);
  void setWindowLevel(double window, double level);
  void resetCamera();
  int sliceIndex() const;
  // The world point under a widget position, on the current slice plane.
  Point worldAt(const QPointF& position) const;
  // The direction letters at the left, right, top and bottom edges, e.g. "R L A P" for the axial view.
  QString orientationLetters() const;

 signals:
  void cursorPicked(const Point& point);  // left click or drag
  void windowLevelDragged(double window, double level);
  void sliceStepped(int steps);  // wheel

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  void updateCrosshair();
  void updateOrientationLetters();

  int axis_;
  vtkNew<vtkRenderer> renderer_;
  vtkNew<vtkImageSliceMapper> mapper_;
  vtkNew<vtkImageSlice> slice_;
  vtkNew<vtkPolyData> crosshair_;
  vtkNew<vtkActor> crosshairActor_;
  std::array<vtkNew<vtkTextActor>, 4> letters_;  // left, right, top, bottom
  vtkSmartPointer<vtkImageData> volume_;
  Point cursor_{0, 0, 0};
  Qt::MouseButton dragging_ = Qt::NoButton;
  QPointF dragStart_;
  double startWindow_ = 1, startLevel_ = 0;
  int wheelRemainder_ = 0;
};

}  // namespace medial::gui
