// ViewGeometry: between widget positions in the 3-D view and the world: the pointer's ray, its point on a
// plane, and where a world point shows. Widget positions are Qt's (logical pixels, y down).
#pragma once

#include <QPointF>

#include <Eigen/Core>

class QWidget;
class vtkRenderer;

namespace medial::gui {

// The pointer's ray from the near to the far clipping plane; false when the camera cannot invert.
bool pointerRay(vtkRenderer* renderer, const QWidget* view, const QPointF& position,
                Eigen::Vector3d& nearPoint, Eigen::Vector3d& farPoint);

// Where the pointer's ray meets the plane through `origin` with `normal`; false when it runs along it.
bool viewPlanePoint(vtkRenderer* renderer, const QWidget* view, const QPointF& position,
                    const Eigen::Vector3d& origin, const Eigen::Vector3d& normal, Eigen::Vector3d& point);

// The widget position where `world` shows.
QPointF widgetPosition(vtkRenderer* renderer, const QWidget* view, const Eigen::Vector3d& world);

}  // namespace medial::gui
