/// \file
/// BoundedDP: stage 3 of the sketch skeletonization (Ma et al. 2021, §3.1, Algorithms 1 and 2, Fig. 7):
/// simplification of one skeleton branch that weighs both the axis and the shape around it.
///
/// A spline (centripetal Catmull-Rom) through the branch's nodes is sampled uniformly, p_i every
/// `sliceStep`; at each p_i the line perpendicular to the axis is cut with the polygon, giving the segment
/// s_i (half-widths d+_i to the left and d-_i to the right, capped at twice the inscribed radius where a
/// perpendicular runs along a bent tube); the slices make up the general-cylinder region Omega.
/// Douglas-Peucker then picks, in each range [st, en], the sample with the largest error (eq. 1)
///     E_i = E_p + alpha_s E_s,
/// E_p the distance from p_i to the line p_st p_en and E_s = |d+_i - w+_i| + |d-_i - w-_i|, the distances of
/// the segment's ends to the sides of the trapezoid spanned by s_st and s_en on the straightened axis (w+-
/// interpolated linearly in arc length). A range is split while E_max > epsilon (the listing of Algorithm 1
/// marks i_max before its test, which would keep a joint in the middle of every straight bone; we keep it
/// only when E_max > epsilon, as Douglas-Peucker does and as a rectangle needs to stay one bone).
/// Algorithm 2: while an edge of the simplified polyline leaves Omega (it misses a slice between its ends, or
/// crosses the outline), epsilon is lowered by the ratio 0.8.
/// The thresholds tried lie on one fixed ladder unit x 0.8^k, starting at the rung at or below the user's
/// epsilon: then a larger epsilon never yields more joints (the ladder below it is the same).
#pragma once

#include "sketch/SketchStroke.h"

#include <vector>

namespace medial {

/// BoundedDP's parameters (Ma et al. 2021 \cite ma2021, Algorithms 1-2).
struct BoundedDPParameters {
  double threshold = 5;      ///< epsilon_s, in the same length unit as the points (already scaled)
  double shapeWeight = 1;    ///< alpha_s (the paper gives no value; 1 weighs axis and outline alike)
  double sliceStep = 2;      ///< arc length between slices
  double tuningRatio = 0.8;  ///< Algorithm 2's factor
  double ladderUnit = 1;     ///< the ladder's rung 0 (one sketch pixel)
};

/// A branch simplified by boundedDP().
struct BoundedDPResult {
  std::vector<Eigen::Vector2d> points;  ///< the simplified polyline, first and last node of the branch kept
  double threshold = 0;                 ///< the epsilon that was accepted
  bool inside = true;  ///< false when even the finest threshold left Omega (kept all samples)
};

/// Algorithms 1-2: the branch simplified by Douglas-Peucker with the largest threshold on the
/// ladder whose spline through the kept points stays inside `polygon` (Omega) and keeps its shape.
BoundedDPResult boundedDP(const std::vector<Eigen::Vector2d>& branch, const Polygon2& polygon,
                          const BoundedDPParameters& parameters);

/// Points every `step` of arc length along a centripetal Catmull-Rom spline through `nodes` (the first and
/// last node included).
std::vector<Eigen::Vector2d> sampleSpline(const std::vector<Eigen::Vector2d>& nodes, double step);

}  // namespace medial
