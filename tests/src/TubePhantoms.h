// Binary tube phantoms with analytic axes for the centerline tests: a curve c(s), s in [0, 1], swept by a
// ball of radius R and voxelized on a grid.
#pragma once

#include "centerline/BinaryVolume.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace medial::testing {

struct TubePhantom {
  BinaryVolume volume;
  std::vector<Eigen::Vector3d> axis;  // dense samples of the true axis (physical)
  double radius = 0;
};

inline double distanceToPolyline(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& line) {
  double best = INFINITY;
  for (size_t k = 0; k + 1 < line.size(); ++k) {
    const Eigen::Vector3d a = line[k], ab = line[k + 1] - a;
    const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (a + t * ab - p).norm());
  }
  return best;
}

inline TubePhantom tubePhantom(const std::function<Eigen::Vector3d(double)>& curve, double radius,
                               std::array<int, 3> size, Eigen::Vector3d spacing = Eigen::Vector3d::Ones()) {
  TubePhantom t;
  t.radius = radius;
  t.volume.size = size;
  t.volume.spacing = spacing;
  t.volume.inside.assign(size_t(t.volume.voxelCount()), 0);
  for (int i = 0; i <= 500; ++i) t.axis.push_back(curve(i / 500.0));
  for (int64_t i = 0; i < t.volume.voxelCount(); ++i)
    t.volume.inside[size_t(i)] = distanceToPolyline(t.volume.physical(i), t.axis) <= radius;
  return t;
}

// Mean and max distance (physical) from centerline points to the true axis, leaving out the points within
// one radius of the axis ends (the caps of a swept ball, where no method finds the curve's end).
struct AxisError {
  double mean = 0, max = 0;
  int points = 0;
};

inline AxisError axisError(const std::vector<Eigen::Vector3d>& points, const TubePhantom& t) {
  AxisError e;
  for (const auto& p : points) {
    if ((p - t.axis.front()).norm() < t.radius || (p - t.axis.back()).norm() < t.radius) continue;
    const double d = distanceToPolyline(p, t.axis);
    e.mean += d;
    e.max = std::max(e.max, d);
    ++e.points;
  }
  if (e.points > 0) e.mean /= e.points;
  return e;
}

}  // namespace medial::testing
