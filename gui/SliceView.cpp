#include "SliceView.h"

#include <QMouseEvent>
#include <QStringList>
#include <QWheelEvent>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkImageData.h>
#include <vtkImageProperty.h>
#include <vtkImageSlice.h>
#include <vtkImageSliceMapper.h>
#include <vtkInteractorStyleImage.h>
#include <vtkMath.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkGenericRenderWindowInteractor.h>

#include <algorithm>
#include <cmath>

namespace medial::gui {

SliceView::SliceView(int axis, QWidget* parent) : VtkView(parent), axis_(axis) {
  setMinimumSize(120, 120);
  renderer_->SetBackground(0, 0, 0);
  mapper_->SetOrientation(axis_);
  slice_->SetMapper(mapper_);
  slice_->GetProperty()->SetInterpolationTypeToLinear();
  slice_->VisibilityOff();
  renderer_->AddViewProp(slice_);

  auto mapper = vtkNew<vtkPolyDataMapper>();
  mapper->SetInputData(crosshair_);
  crosshairActor_->SetMapper(mapper);
  crosshairActor_->GetProperty()->SetColor(1.0, 0.85, 0.1);
  crosshairActor_->GetProperty()->SetLineWidth(1.5);
  crosshairActor_->GetProperty()->LightingOff();
  crosshairActor_->VisibilityOff();
  renderer_->AddActor(crosshairActor_);
  const double anchors[4][2] = {{0.01, 0.5}, {0.99, 0.5}, {0.5, 0.99}, {0.5, 0.01}};
  for (int k = 0; k < 4; ++k) {
    vtkTextProperty* text = letters_[size_t(k)]->GetTextProperty();
    text->SetFontSize(14);
    text->BoldOn();
    text->SetColor(1.0, 0.85, 0.1);  // the crosshair's yellow
    text->SetJustification(k == 0 ? VTK_TEXT_LEFT : k == 1 ? VTK_TEXT_RIGHT : VTK_TEXT_CENTERED);
    text->SetVerticalJustification(k == 2 ? VTK_TEXT_TOP : k == 3 ? VTK_TEXT_BOTTOM : VTK_TEXT_CENTERED);
    letters_[size_t(k)]->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    letters_[size_t(k)]->SetPosition(anchors[k][0], anchors[k][1]);
    letters_[size_t(k)]->VisibilityOff();
    renderer_->AddActor2D(letters_[size_t(k)]);
  }
  addRenderer(renderer_);

  auto style = vtkNew<vtkInteractorStyleImage>();  // middle-drag pan, Ctrl+wheel zoom
  interactor()->SetInteractorStyle(style);
}

SliceView::~SliceView() = default;

void SliceView::setVolume(vtkImageData* volume) {
  volume_ = volume;
  const bool show = volume != nullptr;
  slice_->SetVisibility(show);
  crosshairActor_->SetVisibility(show);
  for (auto& letter : letters_) letter->SetVisibility(show);
  if (!volume) {
    update();
    return;
  }
  mapper_->SetInputData(volume);
  double center[3];
  volume->GetCenter(center);
  cursor_ = {center[0], center[1], center[2]};
  setCursor(cursor_);
  resetCamera();
}

int SliceView::sliceIndex() const {
  if (!volume_) return 0;
  const int* extent = volume_->GetExtent();
  const double index = (cursor_[axis_] - volume_->GetOrigin()[axis_]) / volume_->GetSpacing()[axis_];
  return std::clamp(static_cast<int>(std::lround(index)), extent[2 * axis_], extent[2 * axis_ + 1]);
}

void SliceView::setCursor(const Point& cursor) {
  cursor_ = cursor;
  if (!volume_) return;
  mapper_->SetSliceNumber(sliceIndex());
  updateCrosshair();
  update();
}

void SliceView::setWindowLevel(double window, double level) {
  slice_->GetProperty()->SetColorWindow(std::max(window, 1e-6));
  slice_->GetProperty()->SetColorLevel(level);
  update();
}

void SliceView::updateCrosshair() {
  // Two lines through the cursor across the volume, in the slice plane, nudged towards the camera.
  double bounds[6];
  volume_->GetBounds(bounds);
  const int u = (axis_ + 1) % 3, v = (axis_ + 2) % 3;
  const double lift = 0.01 * volume_->GetSpacing()[axis_];
  auto points = vtkNew<vtkPoints>();
  for (int line = 0; line < 2; ++line) {
    const int along = line == 0 ? u : v;
    for (int end = 0; end < 2; ++end) {
      Point p = cursor_;
      p[along] = bounds[2 * along + end];
      // The camera looks along +z (axial), +y (coronal), -x (sagittal): lift against that direction.
      p[axis_] = volume_->GetOrigin()[axis_] + sliceIndex() * volume_->GetSpacing()[axis_] +
                 (axis_ == 0 ? lift : -lift);
      points->InsertNextPoint(p.data());
    }
  }
  auto lines = vtkNew<vtkCellArray>();
  const vtkIdType first[2] = {0, 1}, second[2] = {2, 3};
  lines->InsertNextCell(2, first);
  lines->InsertNextCell(2, second);
  crosshair_->SetPoints(points);
  crosshair_->SetLines(lines);
  crosshair_->Modified();
}

void SliceView::resetCamera() {
  if (!volume_) return;
  // Axial seen from the feet (anterior up), coronal from the front, sagittal from the left: the usual
  // radiological views for LPS data.
  vtkCamera* camera = renderer_->GetActiveCamera();
  double center[3];
  volume_->GetCenter(center);
  double direction[3] = {0, 0, 0}, up[3] = {0, 0, 0};
  if (axis_ == 2) direction[2] = 1, up[1] = -1;
  if (axis_ == 1) direction[1] = 1, up[2] = 1;
  if (axis_ == 0) direction[0] = -1, up[2] = 1;
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] - direction[0], center[1] - direction[1], center[2] - direction[2]);
  camera->SetViewUp(up);
  renderer_->ResetCamera();
  double bounds[6];
  volume_->GetBounds(bounds);
  const int u = (axis_ + 1) % 3, v = (axis_ + 2) % 3;
  const double aspect = height() > 0 ? static_cast<double>(width()) / height() : 1.0;
  const double horizontal =
      axis_ == 2 ? bounds[1] - bounds[0]
                 : std::max(bounds[2 * u + 1] - bounds[2 * u], bounds[2 * v + 1] - bounds[2 * v]);
  const double vertical = axis_ == 2 ? bounds[3] - bounds[2] : bounds[5] - bounds[4];
  camera->SetParallelScale(0.52 * std::max(vertical, horizontal / aspect));
  updateOrientationLetters();
  update();
}

namespace {

// The patient direction a world direction points to most, in ITK's LPS frame (+x left, +y posterior,
// +z superior), as radiologists label the edges of a slice.
const char* patientDirection(const double d[3]) {
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(d[i]) > std::fabs(d[axis])) axis = i;
  const char* letters[3][2] = {{"R", "L"}, {"A", "P"}, {"I", "S"}};
  return letters[axis][d[axis] > 0 ? 1 : 0];
}

}  // namespace

void SliceView::updateOrientationLetters() {
  vtkCamera* camera = renderer_->GetActiveCamera();
  double forward[3], up[3], right[3];
  camera->GetDirectionOfProjection(forward);
  camera->GetViewUp(up);
  vtkMath::Cross(forward, up, right);  // the screen's right in the world
  const double left[3] = {-right[0], -right[1], -right[2]}, down[3] = {-up[0], -up[1], -up[2]};
  const double* directions[4] = {left, right, up, down};
  for (int k = 0; k < 4; ++k) {
    letters_[size_t(k)]->SetInput(patientDirection(directions[k]));
    letters_[size_t(k)]->SetVisibility(volume_ != nullptr);
  }
}

QString SliceView::orientationLetters() const {
  QStringList letters;
  for (const auto& letter : letters_) letters << letter->GetInput();
  return letters.join(' ');
}

SliceView::Point SliceView::worldAt(const QPointF& position) const {
  const qreal ratio = devicePixelRatioF();
  const double x = position.x() * ratio, y = (height() - position.y()) * ratio;
  renderer_->SetDisplayPoint(x, y, 0.5);
  renderer_->DisplayToWorld();
  double world[4];
  renderer_->GetWorldPoint(world);
  Point p{world[0], world[1], world[2]};
  if (world[3] != 0 && world[3] != 1)
    for (int i = 0; i < 3; ++i) p[i] = world[i] / world[3];
  p[axis_] = cursor_[axis_];
  return p;
}

void SliceView::mousePressEvent(QMouseEvent* event) {
  if (!volume_ || (event->button() != Qt::LeftButton && event->button() != Qt::RightButton)) {
    VtkView::mousePressEvent(event);
    return;
  }
  dragging_ = event->button();
  dragStart_ = event->position();
  startWindow_ = slice_->GetProperty()->GetColorWindow();
  startLevel_ = slice_->GetProperty()->GetColorLevel();
  if (dragging_ == Qt::LeftButton) emit cursorPicked(worldAt(event->position()));
}

void SliceView::mouseMoveEvent(QMouseEvent* event) {
  if (dragging_ == Qt::LeftButton) {
    emit cursorPicked(worldAt(event->position()));
  } else if (dragging_ == Qt::RightButton) {
    // As in 3D Slicer: horizontal drag widens the window, vertical drag raises the level; a drag across
    // the view changes them by about the starting window.
    const QPointF delta = event->position() - dragStart_;
    const double scale = std::max(startWindow_, 1.0) / std::max(width(), 1);
    emit windowLevelDragged(std::max(1.0, startWindow_ + delta.x() * scale), startLevel_ - delta.y() * scale);
  } else {
    VtkView::mouseMoveEvent(event);
  }
}

void SliceView::mouseReleaseEvent(QMouseEvent* event) {
  if (dragging_ != Qt::NoButton && event->button() == dragging_) {
    dragging_ = Qt::NoButton;
    return;
  }
  VtkView::mouseReleaseEvent(event);
}

void SliceView::wheelEvent(QWheelEvent* event) {
  if (!volume_ || (event->modifiers() & Qt::ControlModifier)) {
    VtkView::wheelEvent(event);
    return;
  }
  wheelRemainder_ += event->angleDelta().y();
  const int steps = wheelRemainder_ / 120;
  wheelRemainder_ -= steps * 120;
  if (steps != 0) emit sliceStepped(steps);
  event->accept();
}

}  // namespace medial::gui
