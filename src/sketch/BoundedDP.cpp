#include "sketch/BoundedDP.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace medial {
namespace {

// Centripetal Catmull-Rom point between p1 and p2 (Barry-Goldman pyramid), t in [0, 1].
Eigen::Vector2d catmullRom(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2,
                           const Eigen::Vector2d& p3, double t) {
  auto knot = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::max(1e-12, std::sqrt((b - a).norm()));
  };
  const double t0 = 0, t1 = t0 + knot(p0, p1), t2 = t1 + knot(p1, p2), t3 = t2 + knot(p2, p3);
  const double u = t1 + t * (t2 - t1);
  const Eigen::Vector2d a1 = (t1 - u) / (t1 - t0) * p0 + (u - t0) / (t1 - t0) * p1;
  const Eigen::Vector2d a2 = (t2 - u) / (t2 - t1) * p1 + (u - t1) / (t2 - t1) * p2;
  const Eigen::Vector2d a3 = (t3 - u) / (t3 - t2) * p2 + (u - t2) / (t3 - t2) * p3;
  const Eigen::Vector2d b1 = (t2 - u) / (t2 - t0) * a1 + (u - t0) / (t2 - t0) * a2;
  const Eigen::Vector2d b2 = (t3 - u) / (t3 - t1) * a2 + (u - t1) / (t3 - t1) * a3;
  return (t2 - u) / (t2 - t1) * b1 + (u - t1) / (t2 - t1) * b2;
}

// One pass over the polygon's edges for a slice at p with unit normal n: the inscribed radius (distance
// to the boundary) and the first boundary hits along +n and -n (0 when nothing is hit). One loop instead
// of three, and squared distances with one square root: this runs every 2 px along every branch.
struct SliceWidths {
  double radius, plus, minus;
};

SliceWidths sliceWidths(const Polygon2& polygon, const Eigen::Vector2d& p, const Eigen::Vector2d& n) {
  double nearest = std::numeric_limits<double>::infinity();
  double plus = std::numeric_limits<double>::infinity(), minus = plus;
  for (size_t i = 0, count = polygon.size(); i < count; ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % count];
    nearest = std::min(nearest, squaredDistanceToSegment(p, a, b));
    const Eigen::Vector2d e = b - a;
    const double denominator = cross2(n, e);
    if (std::abs(denominator) < 1e-300) continue;
    const double s = cross2(a - p, e) / denominator;  // along the normal line through p
    const double u = cross2(a - p, n) / denominator;  // along the edge
    if (u < 0 || u > 1) continue;
    if (s > 0) plus = std::min(plus, s);
    if (s < 0) minus = std::min(minus, -s);
  }
  return {std::sqrt(nearest), std::isfinite(plus) ? plus : 0.0, std::isfinite(minus) ? minus : 0.0};
}

struct Slices {
  std::vector<Eigen::Vector2d> points;             // p_i
  std::vector<double> arc, widthLeft, widthRight;  // arc length of p_i, d+_i, d-_i
};

Slices slice(const std::vector<Eigen::Vector2d>& samples, const Polygon2& polygon) {
  Slices s;
  s.points = samples;
  const size_t n = samples.size();
  double travelled = 0;
  for (size_t i = 0; i < n; ++i) {
    if (i > 0) travelled += (samples[i] - samples[i - 1]).norm();
    const Eigen::Vector2d tangent =
        (samples[std::min(i + 1, n - 1)] - samples[i > 0 ? i - 1 : 0]).normalized();
    const Eigen::Vector2d normal(-tangent.y(), tangent.x());
    // Where the axis bends sharply, a perpendicular can run along the tube instead of across it; no
    // half-width of a general cylinder exceeds twice its inscribed radius, so longer hits are capped.
    const SliceWidths widths = sliceWidths(polygon, samples[i], normal);
    const double cap = 2 * widths.radius;
    const double plus = std::min(cap, widths.plus);
    const double minus = std::min(cap, widths.minus);
    s.arc.push_back(travelled);
    s.widthLeft.push_back(plus > 0 ? plus : cap / 2);
    s.widthRight.push_back(minus > 0 ? minus : cap / 2);
  }
  return s;
}

// Algorithm 1 (with alpha_s of eq. 1 and the threshold test before marking, see the header).
void selectPoints(const Slices& s, int first, int last, double epsilon, double alpha,
                  std::vector<char>& keep) {
  if (last <= first + 1) return;
  const Eigen::Vector2d a = s.points[first], b = s.points[last];
  const Eigen::Vector2d chord = b - a;
  const double chordLength = chord.norm();
  const double span = s.arc[last] - s.arc[first];
  int best = first;
  double bestError = 0;
  for (int i = first + 1; i < last; ++i) {
    const double axis =
        chordLength > 0 ? std::abs(cross2(chord, s.points[i] - a)) / chordLength : (s.points[i] - a).norm();
    const double t = span > 0 ? (s.arc[i] - s.arc[first]) / span : 0.0;
    const double sideLeft = (1 - t) * s.widthLeft[first] + t * s.widthLeft[last];
    const double sideRight = (1 - t) * s.widthRight[first] + t * s.widthRight[last];
    const double shape = std::abs(s.widthLeft[i] - sideLeft) + std::abs(s.widthRight[i] - sideRight);
    const double error = axis + alpha * shape;
    if (error > bestError) bestError = error, best = i;
  }
  if (bestError <= epsilon) return;
  keep[best] = 1;
  selectPoints(s, first, best, epsilon, alpha, keep);
  selectPoints(s, best, last, epsilon, alpha, keep);
}

// IsInsideShape of Algorithm 2: an edge p_i p_j of the polyline stays in Omega when it crosses every slice
// s_k between its ends within the slice (its distance to p_k at most the half-width on the side it passes)
// and never crosses the outline. Slice by slice rather than against the two side lines of Omega, which
// fold over themselves where the axis bends.
bool insideRegion(const Slices& s, const std::vector<int>& kept, const Polygon2& polygon) {
  for (size_t k = 0; k + 1 < kept.size(); ++k) {
    const int i = kept[k], j = kept[k + 1];
    if (j == i + 1) continue;  // consecutive samples follow the axis itself
    const Eigen::Vector2d& a = s.points[i];
    const Eigen::Vector2d& b = s.points[j];
    const Eigen::Vector2d ab = b - a;
    for (int m = i + 1; m < j; ++m) {
      const Eigen::Vector2d& p = s.points[m];
      const double t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
      const double distance = (a + t * ab - p).norm();
      const bool edgeOnTheLeft = cross2(ab, p - a) < 0;  // p lies right of the edge
      if (distance > (edgeOnTheLeft ? s.widthLeft[m] : s.widthRight[m])) return false;
    }
    for (size_t e = 0, n = polygon.size(); e < n; ++e)
      if (segmentsIntersect(a, b, polygon[e], polygon[(e + 1) % n])) return false;
  }
  return true;
}

}  // namespace

std::vector<Eigen::Vector2d> sampleSpline(const std::vector<Eigen::Vector2d>& nodes, double step) {
  const size_t n = nodes.size();
  if (n < 2) return nodes;
  // Dense polyline along the spline (16 pieces per span), then uniform resampling by arc length.
  std::vector<Eigen::Vector2d> dense;
  for (size_t i = 0; i + 1 < n; ++i) {
    const Eigen::Vector2d p0 = i > 0 ? nodes[i - 1] : 2 * nodes[0] - nodes[1];
    const Eigen::Vector2d p3 = i + 2 < n ? nodes[i + 2] : 2 * nodes[n - 1] - nodes[n - 2];
    for (int k = 0; k < 16; ++k) dense.push_back(catmullRom(p0, nodes[i], nodes[i + 1], p3, k / 16.0));
  }
  dense.push_back(nodes.back());
  double total = 0;
  for (size_t i = 1; i < dense.size(); ++i) total += (dense[i] - dense[i - 1]).norm();
  const int pieces = std::max(2, int(std::round(total / step)));
  const double spacing = total / pieces;
  std::vector<Eigen::Vector2d> samples{dense.front()};
  double travelled = 0;
  size_t segment = 0;
  for (int k = 1; k < pieces; ++k) {
    const double target = k * spacing;
    double length = (dense[segment + 1] - dense[segment]).norm();
    while (travelled + length < target && segment + 2 < dense.size()) {
      travelled += length;
      ++segment;
      length = (dense[segment + 1] - dense[segment]).norm();
    }
    const double t = length > 0 ? std::clamp((target - travelled) / length, 0.0, 1.0) : 0.0;
    samples.push_back(dense[segment] + t * (dense[segment + 1] - dense[segment]));
  }
  samples.push_back(dense.back());
  return samples;
}

BoundedDPResult boundedDP(const std::vector<Eigen::Vector2d>& branch, const Polygon2& polygon,
                          const BoundedDPParameters& parameters) {
  BoundedDPResult result;
  if (branch.size() <= 2) {
    result.points = branch;
    result.threshold = parameters.threshold;
    return result;
  }
  const Slices s = slice(sampleSpline(branch, parameters.sliceStep), polygon);
  const int n = int(s.points.size());
  // The ladder: unit x ratio^k; start at the rung at or below the threshold.
  const double ratio = parameters.tuningRatio;
  const double unit = parameters.ladderUnit;
  int rung = int(std::ceil(std::log(std::max(parameters.threshold, 1e-300) / unit) / std::log(ratio) - 1e-9));
  for (int iteration = 0; iteration < 200; ++iteration, ++rung) {
    const double epsilon = unit * std::pow(ratio, rung);
    std::vector<char> keep(n, 0);
    keep[0] = keep[n - 1] = 1;
    selectPoints(s, 0, n - 1, epsilon, parameters.shapeWeight, keep);
    std::vector<int> kept;
    for (int i = 0; i < n; ++i)
      if (keep[i]) kept.push_back(i);
    const bool everything = int(kept.size()) == n;
    const bool inside = insideRegion(s, kept, polygon);
    if (inside || everything) {
      for (int i : kept) result.points.push_back(s.points[i]);
      result.threshold = epsilon;
      result.inside = inside;
      return result;
    }
  }
  result.points = s.points;
  result.threshold = 0;
  result.inside = false;
  return result;
}

}  // namespace medial
