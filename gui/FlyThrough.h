// FlyThrough: an endoscopic camera path along a centerline: the eye at a point of the line, looking at a
// point a little further along (about one local diameter), the up vector carried along the path so that
// the view does not spin. Positions are in arc length (mm).
#pragma once

#include <vtkSmartPointer.h>

#include <array>
#include <vector>

class vtkCamera;
class vtkPolyData;

namespace medial::gui {

class FlyThrough {
 public:
  using Point = std::array<double, 3>;

  // Takes the first polyline of `centerline` (its `ArcLength` and `Radius` when present). False when it
  // has fewer than two points.
  bool setPath(vtkPolyData* centerline);
  bool empty() const { return points_.size() < 2; }
  double length() const { return arc_.empty() ? 0.0 : arc_.back(); }

  // The camera pose at arc length s (clamped to the path), looking forward (towards the end of the path) or
  // backward.
  Point eye(double s) const;
  Point focal(double s, bool backward = false) const;
  Point up(double s, bool backward = false) const;
  // Puts the camera at arc length s: eye, focal point, up, and a view angle in degrees (an endoscope's wide
  // 80 by default).
  void apply(vtkCamera* camera, double s, bool backward = false, double viewAngle = 80.0) const;

 private:
  Point at(double s) const;
  double radiusAt(double s) const;
  size_t indexAt(double s) const;  // the first path point at or beyond arc length s

  std::vector<Point> points_;
  std::vector<double> arc_;
  std::vector<double> radius_;
  std::vector<Point> ups_;  // per point, perpendicular to the path, transported along it
};

}  // namespace medial::gui
