/// \file
/// SketchStroke: stage 1 of the sketch skeletonization (Ma et al. 2021, "Real-time skeletonization for
/// sketch-based modeling", §3.1 "Simple polygon acquisition"): a raw closed stroke becomes the simple,
/// counter-clockwise polygon the straight skeleton is computed on.
///
/// Steps: drop repeated consecutive points, check the stroke (>= 3 distinct points, finite, non-zero area),
/// resample it uniformly by arc length (this smooths the jitter of an unsteady hand, Fig. 19), check that
/// the resampled polygon is simple (Definition 1), simplify it with Douglas-Peucker [9] and orient it
/// counter-clockwise. When simplification would make the polygon cross itself, the tolerance is halved
/// until it does not.
#pragma once

#include <Eigen/Core>

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace medial {

using Polygon2 = std::vector<Eigen::Vector2d>;  ///< closed: the last vertex joins the first

/// How a stroke is resampled and simplified into the part's polygon.
struct StrokeParameters {
  double resampleStep = 10;  ///< arc length between resampled points (the paper's 10 px for a 1972 px stroke)
  double tolerance = 2;      ///< Douglas-Peucker tolerance of the polygon
};

/// A stroke ready for the straight skeleton.
struct PreparedStroke {
  Polygon2 resampled;  ///< uniform, counter-clockwise, simple
  Polygon2 polygon;    ///< Douglas-Peucker simplification of `resampled`, counter-clockwise, simple
  std::string error;   ///< empty on success
  /// True when the work succeeded (no error).
  bool ok() const { return error.empty(); }
};

/// The stroke resampled, made counter-clockwise and simplified; an error when it is not a simple
/// polygon (it crosses itself) or has too few points.
PreparedStroke prepareStroke(const Polygon2& stroke, const StrokeParameters& parameters);

/// z of the cross product of two plane vectors (> 0: b turns left of a).
inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}
/// Signed area (> 0 for counter-clockwise).
double signedArea(const Polygon2& polygon);
/// Total length of the closed polyline.
double perimeter(const Polygon2& polygon);
/// Points along the closed polyline, each at straight distance `step` from the previous one.
Polygon2 resampleClosed(const Polygon2& stroke, double step);
/// Douglas-Peucker on a closed polygon: the two mutually farthest-apart vertices are kept and each of the
/// two chains between them is simplified; returns the kept vertices in order.
Polygon2 simplifyClosed(const Polygon2& polygon, double tolerance);
/// Index pair (i, j) of two non-adjacent edges that cross or touch, or (-1, -1) when the polygon is simple.
std::pair<int, int> findSelfIntersection(const Polygon2& polygon);
/// Distance from p to the closed polygon's boundary; `inside` tells whether p is strictly inside.
double distanceToBoundary(const Polygon2& polygon, const Eigen::Vector2d& p, bool* inside = nullptr);
/// Squared distance from p to the segment ab.
double squaredDistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b);
/// Whether p lies strictly inside the closed polygon.
bool isInside(const Polygon2& polygon, const Eigen::Vector2d& p);
/// Whether the open segments ab and cd intersect (touching counts).
bool segmentsIntersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                       const Eigen::Vector2d& d);

}  // namespace medial
