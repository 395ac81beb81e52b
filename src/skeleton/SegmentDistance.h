/// \file
/// SegmentDistance: the point of a bone (a segment between two skeleton nodes) nearest a point, and the
/// distance to it - what the heat weights, the rig's ground root and the rig importer measure.
#pragma once

#include <Eigen/Core>

#include <algorithm>

namespace medial {

/// The point of segment a-b nearest `p` (a for a degenerate segment).
inline Eigen::Vector3d closestPointOnSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                             const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

/// The distance from `p` to segment a-b.
inline double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                const Eigen::Vector3d& b) {
  return (closestPointOnSegment(p, a, b) - p).norm();
}

}  // namespace medial
