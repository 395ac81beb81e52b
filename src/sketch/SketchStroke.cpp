#include "sketch/SketchStroke.h"

#include <algorithm>
#include <limits>
#include <cmath>
#include <sstream>

namespace medial {
namespace {

double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::sqrt(squaredDistanceToSegment(p, a, b));
}

// Classic Douglas-Peucker [9] on the open chain points[first..last]: marks the kept points.
void douglasPeucker(const Polygon2& points, int first, int last, double tolerance, std::vector<char>& keep) {
  if (last <= first + 1) return;
  double farthest = -1;
  int index = first;
  for (int i = first + 1; i < last; ++i) {
    const double d = distanceToSegment(points[i], points[first], points[last]);
    if (d > farthest) farthest = d, index = i;
  }
  if (farthest <= tolerance) return;
  keep[index] = 1;
  douglasPeucker(points, first, index, tolerance, keep);
  douglasPeucker(points, index, last, tolerance, keep);
}

std::string at(const Eigen::Vector2d& p) {
  std::ostringstream text;
  text << "(" << p.x() << ", " << p.y() << ")";
  return text.str();
}

}  // namespace

double signedArea(const Polygon2& polygon) {
  double twice = 0;
  for (size_t i = 0, n = polygon.size(); i < n; ++i) twice += cross2(polygon[i], polygon[(i + 1) % n]);
  return 0.5 * twice;
}

double perimeter(const Polygon2& polygon) {
  double length = 0;
  for (size_t i = 0, n = polygon.size(); i < n; ++i) length += (polygon[(i + 1) % n] - polygon[i]).norm();
  return length;
}

Polygon2 resampleClosed(const Polygon2& stroke, double step) {
  // Walk the stroke and drop a point each time the straight distance from the last one reaches `step`
  // (on the segment where it does). Measuring chords rather than arc length keeps the spacing uniform on
  // a jittery stroke, whose arc is much longer than its chords. Each point is then replaced by the mean of
  // the stroke over its window (half-way to its neighbours, by arc length): jitter shorter than the step
  // is averaged away, straight runs do not move, corners are cut by a fraction of the step.
  const size_t n = stroke.size();
  std::vector<double> arcAt(n + 1, 0.0);  // arc length at raw vertex i (index n: back to the start)
  for (size_t i = 1; i <= n; ++i) arcAt[i] = arcAt[i - 1] + (stroke[i % n] - stroke[i - 1]).norm();
  Polygon2 points{stroke[0]};
  std::vector<double> arcs{0.0};
  for (size_t i = 1; i <= n; ++i) {
    const Eigen::Vector2d a = stroke[i - 1], b = stroke[i % n];
    double from = 0;  // parameter on [a, b] already passed
    while (true) {
      const Eigen::Vector2d d = b - a, f = a - points.back();
      const double qa = d.squaredNorm(), qb = 2 * f.dot(d), qc = f.squaredNorm() - step * step;
      const double discriminant = qb * qb - 4 * qa * qc;
      if (qa <= 0 || discriminant < 0) break;
      const double t = (-qb + std::sqrt(discriminant)) / (2 * qa);  // where the segment leaves the circle
      if (t < from || t > 1) break;
      points.push_back(a + t * d);
      arcs.push_back(arcAt[i - 1] + t * (arcAt[i] - arcAt[i - 1]));
      from = t;
    }
  }
  while (points.size() > 3 && (points.back() - points.front()).norm() < 0.5 * step)
    points.pop_back(), arcs.pop_back();
  const size_t m = points.size();
  if (m < 3) return points;
  // Mean of the closed polyline over the arc window [from, to] (may wrap around).
  const double total = arcAt[n];
  auto pointAt = [&](size_t i) { return stroke[i % n]; };
  auto integral = [&](double from, double to) {  // integral of the curve over [from, to] within one lap
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    size_t i = size_t(std::upper_bound(arcAt.begin(), arcAt.end(), from) - arcAt.begin());
    for (i = i > 0 ? i - 1 : 0; i < n && arcAt[i] < to; ++i) {
      const double s0 = std::max(from, arcAt[i]), s1 = std::min(to, arcAt[i + 1]);
      const double length = arcAt[i + 1] - arcAt[i];
      if (s1 <= s0 || length <= 0) continue;
      const Eigen::Vector2d p0 = pointAt(i) + (s0 - arcAt[i]) / length * (pointAt(i + 1) - pointAt(i));
      const Eigen::Vector2d p1 = pointAt(i) + (s1 - arcAt[i]) / length * (pointAt(i + 1) - pointAt(i));
      sum += 0.5 * (p0 + p1) * (s1 - s0);
    }
    return sum;
  };
  Polygon2 result(m);
  for (size_t k = 0; k < m; ++k) {
    const double previous = k > 0 ? arcs[k - 1] : arcs[m - 1] - total;
    const double next = k + 1 < m ? arcs[k + 1] : arcs[0] + total;
    double from = 0.5 * (previous + arcs[k]), to = 0.5 * (arcs[k] + next);
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    if (from < 0) sum += integral(from + total, total), from = 0;
    if (to > total) sum += integral(0, to - total), to = total;
    sum += integral(from, to);
    const double width = 0.5 * (next - previous);
    result[k] = width > 0 ? Eigen::Vector2d(sum / width) : points[k];
  }
  return result;
}

Polygon2 simplifyClosed(const Polygon2& polygon, double tolerance) {
  const int n = int(polygon.size());
  if (n <= 3) return polygon;
  // Split the loop at two far-apart vertices (two sweeps approximate the diameter).
  auto farthestFrom = [&](int from) {
    int best = from;
    double bestDistance = -1;
    for (int i = 0; i < n; ++i) {
      const double d = (polygon[i] - polygon[from]).squaredNorm();
      if (d > bestDistance) bestDistance = d, best = i;
    }
    return best;
  };
  const int a = farthestFrom(0);
  const int b = farthestFrom(a);
  Polygon2 rotated(polygon.begin() + a, polygon.end());
  rotated.insert(rotated.end(), polygon.begin(), polygon.begin() + a);
  const int split = (b - a + n) % n;
  rotated.push_back(rotated.front());  // close the loop for the second chain
  std::vector<char> keep(rotated.size(), 0);
  keep[0] = keep[split] = 1;
  douglasPeucker(rotated, 0, split, tolerance, keep);
  douglasPeucker(rotated, split, n, tolerance, keep);
  Polygon2 result;
  for (int i = 0; i < n; ++i)
    if (keep[i]) result.push_back(rotated[i]);
  return result;
}

bool segmentsIntersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                       const Eigen::Vector2d& d) {
  if (std::max(a.x(), b.x()) < std::min(c.x(), d.x()) || std::max(c.x(), d.x()) < std::min(a.x(), b.x()) ||
      std::max(a.y(), b.y()) < std::min(c.y(), d.y()) || std::max(c.y(), d.y()) < std::min(a.y(), b.y()))
    return false;
  const double d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a);
  const double d3 = cross2(d - c, a - c), d4 = cross2(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto onSegment = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
  };
  return (d1 == 0 && onSegment(a, b, c)) || (d2 == 0 && onSegment(a, b, d)) ||
         (d3 == 0 && onSegment(c, d, a)) || (d4 == 0 && onSegment(c, d, b));
}

std::pair<int, int> findSelfIntersection(const Polygon2& polygon) {
  const int n = int(polygon.size());
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % n];
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      if (segmentsIntersect(a, b, polygon[j], polygon[(j + 1) % n])) return {i, j};
    }
  }
  return {-1, -1};
}

bool isInside(const Polygon2& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t i = 0, n = polygon.size(), j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

double squaredDistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).squaredNorm();
}

double distanceToBoundary(const Polygon2& polygon, const Eigen::Vector2d& p, bool* inside) {
  double best = std::numeric_limits<double>::infinity();  // squared: one square root at the end
  for (size_t i = 0, n = polygon.size(); i < n; ++i)
    best = std::min(best, squaredDistanceToSegment(p, polygon[i], polygon[(i + 1) % n]));
  if (inside) *inside = isInside(polygon, p);
  return std::sqrt(best);
}

PreparedStroke prepareStroke(const Polygon2& stroke, const StrokeParameters& parameters) {
  PreparedStroke result;
  Polygon2 points;
  for (const Eigen::Vector2d& p : stroke) {
    if (!p.allFinite()) {
      result.error = "the stroke has a non-finite coordinate (NaN or infinity)";
      return result;
    }
    if (points.empty() || p != points.back()) points.push_back(p);  // repeated points carry no shape
  }
  while (points.size() > 1 && points.back() == points.front()) points.pop_back();  // explicit closure
  if (points.size() < 3) {
    result.error = "the stroke has " + std::to_string(points.size()) +
                   " distinct points; a closed stroke needs at least 3";
    return result;
  }
  if (!(parameters.resampleStep > 0) || !(parameters.tolerance >= 0)) {
    result.error = "the resampling step must be > 0 and the simplification tolerance >= 0";
    return result;
  }
  Eigen::AlignedBox2d box;
  for (const auto& p : points) box.extend(p);
  const double diagonal = box.diagonal().norm();
  if (std::abs(signedArea(points)) <= 1e-9 * diagonal * diagonal) {
    result.error = "the stroke encloses no area (its points are collinear)";
    return result;
  }
  // Resample; a step longer than a twelfth of the perimeter would destroy the shape, so cap it.
  const double step = std::min(parameters.resampleStep, perimeter(points) / 12);
  Polygon2 resampled = resampleClosed(points, step);
  if (resampled.size() < 3) {
    result.error = "the stroke is too small for the resampling step";
    return result;
  }
  const auto crossing = findSelfIntersection(resampled);
  if (crossing.first >= 0) {
    result.error = "the stroke crosses itself near " + at(resampled[crossing.first]) +
                   "; draw a simple closed outline (Definition 1)";
    return result;
  }
  if (signedArea(resampled) < 0) std::reverse(resampled.begin(), resampled.end());
  double tolerance = std::min(parameters.tolerance, step);
  Polygon2 polygon = simplifyClosed(resampled, tolerance);
  while (polygon.size() < 3 || findSelfIntersection(polygon).first >= 0 || signedArea(polygon) <= 0) {
    tolerance *= 0.5;
    polygon = tolerance > 1e-6 * diagonal ? simplifyClosed(resampled, tolerance) : resampled;
    if (polygon.size() == resampled.size()) break;
  }
  result.resampled = std::move(resampled);
  result.polygon = std::move(polygon);
  return result;
}

}  // namespace medial
