#include "ViewGeometry.h"

#include <QWidget>

#include <vtkRenderer.h>

#include <cmath>

namespace medial::gui {

bool pointerRay(vtkRenderer* renderer, const QWidget* view, const QPointF& position,
                Eigen::Vector3d& nearPoint, Eigen::Vector3d& farPoint) {
  const qreal ratio = view->devicePixelRatioF();
  const double x = position.x() * ratio, y = (view->height() - position.y()) * ratio;
  Eigen::Vector3d* ends[2] = {&nearPoint, &farPoint};
  for (int i = 0; i < 2; ++i) {
    double world[4];
    renderer->SetDisplayPoint(x, y, i);
    renderer->DisplayToWorld();
    renderer->GetWorldPoint(world);
    if (world[3] == 0) return false;
    *ends[i] = Eigen::Vector3d(world[0], world[1], world[2]) / world[3];
  }
  return true;
}

bool viewPlanePoint(vtkRenderer* renderer, const QWidget* view, const QPointF& position,
                    const Eigen::Vector3d& origin, const Eigen::Vector3d& normal, Eigen::Vector3d& point) {
  Eigen::Vector3d nearPoint, farPoint;
  if (!pointerRay(renderer, view, position, nearPoint, farPoint)) return false;
  const Eigen::Vector3d along = farPoint - nearPoint;
  const double denominator = along.dot(normal);
  if (std::fabs(denominator) < 1e-12) return false;
  point = nearPoint + (origin - nearPoint).dot(normal) / denominator * along;
  return true;
}

QPointF widgetPosition(vtkRenderer* renderer, const QWidget* view, const Eigen::Vector3d& world) {
  renderer->SetWorldPoint(world.x(), world.y(), world.z(), 1.0);
  renderer->WorldToDisplay();
  double display[3];
  renderer->GetDisplayPoint(display);
  const qreal ratio = view->devicePixelRatioF();
  return {display[0] / ratio, view->height() - display[1] / ratio};
}

}  // namespace medial::gui
