#include "FlyThrough.h"

#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>

namespace medial::gui {

namespace {

using Point = FlyThrough::Point;

Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

Point normalized(Point v) {
  const double n = vtkMath::Norm(v.data());
  if (n > 0)
    for (double& c : v) c /= n;
  return v;
}

// v without its component along the unit vector t, normalized.
Point perpendicular(const Point& v, const Point& t) {
  const double d = vtkMath::Dot(v.data(), t.data());
  return normalized({v[0] - d * t[0], v[1] - d * t[1], v[2] - d * t[2]});
}

}  // namespace

bool FlyThrough::setPath(vtkPolyData* centerline) {
  points_.clear(), arc_.clear(), radius_.clear(), ups_.clear();
  if (!centerline || !centerline->GetLines() || centerline->GetNumberOfLines() == 0) return false;
  vtkIdType count;
  const vtkIdType* ids;
  auto lines = centerline->GetLines();
  lines->InitTraversal();
  if (!lines->GetNextCell(count, ids) || count < 2) return false;
  vtkDataArray* radius = centerline->GetPointData()->GetArray("Radius");
  for (vtkIdType i = 0; i < count; ++i) {
    Point p;
    centerline->GetPoint(ids[i], p.data());
    if (!points_.empty() && vtkMath::Distance2BetweenPoints(p.data(), points_.back().data()) == 0) continue;
    arc_.push_back(points_.empty() ? 0.0
                                   : arc_.back() + std::sqrt(vtkMath::Distance2BetweenPoints(
                                                       p.data(), points_.back().data())));
    points_.push_back(p);
    radius_.push_back(radius ? radius->GetComponent(ids[i], 0) : 0.0);
  }
  if (points_.size() < 2) return false;

  // Parallel transport of an up vector: start perpendicular to the first tangent, then at each point
  // remove the new tangent's component (rotation-minimizing in the limit of fine sampling).
  Point tangent = normalized(minus(points_[1], points_[0]));
  Point up = std::fabs(tangent[2]) < 0.9 ? Point{0, 0, 1} : Point{0, 1, 0};
  up = perpendicular(up, tangent);
  for (size_t i = 0; i < points_.size(); ++i) {
    const size_t next = std::min(i + 1, points_.size() - 1), previous = i > 0 ? i - 1 : 0;
    tangent = normalized(minus(points_[next], points_[previous]));
    up = perpendicular(up, tangent);
    ups_.push_back(up);
  }
  return true;
}

Point FlyThrough::at(double s) const {
  s = std::clamp(s, 0.0, length());
  const size_t i =
      std::min<size_t>(std::upper_bound(arc_.begin(), arc_.end(), s) - arc_.begin(), arc_.size() - 1);
  const size_t a = i > 0 ? i - 1 : 0;
  const double span = arc_[i] - arc_[a];
  const double t = span > 0 ? (s - arc_[a]) / span : 0.0;
  return {points_[a][0] + t * (points_[i][0] - points_[a][0]),
          points_[a][1] + t * (points_[i][1] - points_[a][1]),
          points_[a][2] + t * (points_[i][2] - points_[a][2])};
}

size_t FlyThrough::indexAt(double s) const {
  s = std::clamp(s, 0.0, length());
  return std::min<size_t>(std::lower_bound(arc_.begin(), arc_.end(), s) - arc_.begin(), arc_.size() - 1);
}

double FlyThrough::radiusAt(double s) const { return radius_[indexAt(s)]; }

Point FlyThrough::eye(double s) const { return at(s); }

Point FlyThrough::focal(double s, bool backward) const {
  // Look about one diameter ahead (at least 2 % of the path); past an end, continue the path's direction
  // there.
  const double ahead = std::max(2.0 * radiusAt(s), 0.02 * length());
  const double sign = backward ? -1.0 : 1.0, target = s + sign * ahead;
  if (target >= 0 && target <= length()) return at(target);
  const double end = backward ? 0.0 : length();
  const Point last = at(end), before = at(std::clamp(end - sign * ahead, 0.0, length()));
  const Point direction = normalized(minus(last, before));
  const Point e = at(s);
  return {e[0] + ahead * direction[0], e[1] + ahead * direction[1], e[2] + ahead * direction[2]};
}

Point FlyThrough::up(double s, bool backward) const {
  return perpendicular(ups_[indexAt(s)], normalized(minus(focal(s, backward), eye(s))));
}

void FlyThrough::apply(vtkCamera* camera, double s, bool backward, double viewAngle) const {
  if (empty()) return;
  const Point e = eye(s), f = focal(s, backward), u = up(s, backward);
  camera->SetPosition(e.data());
  camera->SetFocalPoint(f.data());
  camera->SetViewUp(u.data());
  camera->SetViewAngle(viewAngle);
  // Near plane close to the eye: we are inside the tube.
  const double depth = std::sqrt(vtkMath::Distance2BetweenPoints(e.data(), f.data()));
  camera->SetClippingRange(std::max(1e-3 * length(), 0.01 * depth), std::max(length(), 10.0 * depth));
}

}  // namespace medial::gui
