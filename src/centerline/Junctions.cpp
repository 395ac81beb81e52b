#include "centerline/Junctions.h"

#include "centerline/GapBridges.h"

#include <algorithm>
#include <cmath>

namespace medial {

namespace {

// The junction curve's tangents, times the chord. The tree phantom's worst distance to the true axis by
// scale: 0.6: 0.62 mm, 0.8: 0.58, 1.0: 0.68, 1.2: 0.83, 1.5: 1.06 (cutting the parent back by 0.85 to 1.3
// times the children's reach did no better).
constexpr double kJunctionTangentScale = 0.8;

double medianRadius(const Centerline& line, double from, double to) {
  std::vector<double> radii;
  for (size_t k = 0; k < line.points.size(); ++k)
    if (line.arcLength[k] >= from && line.arcLength[k] <= to) radii.push_back(line.radius[k]);
  if (radii.empty()) return 0;
  std::nth_element(radii.begin(), radii.begin() + long(radii.size() / 2), radii.end());
  return radii[radii.size() / 2];
}

}  // namespace

void placeJunctions(const BinaryVolume& volume, std::vector<Centerline>& branches,
                    const std::vector<int>& parents) {
  const double step = volume.spacing.minCoeff();
  const double halfVoxel = 0.5 * step;
  for (size_t p = 0; p < branches.size(); ++p) {
    Centerline& parent = branches[p];
    const double length = parent.length();
    const double radius = medianRadius(parent, 0.5 * length, length);
    if (!(radius > 0) || parent.points.size() < 4) continue;
    std::vector<size_t> children;
    double reach = 0;  // how far the children start from the parent's end
    for (size_t c = 0; c < branches.size(); ++c)
      if (parents[c] == int(p) && branches[c].points.size() >= 3 &&
          (branches[c].points.front() - parent.points.back()).norm() < 3 * radius) {
        children.push_back(c);
        reach = std::max(reach, (branches[c].points.front() - parent.points.back()).norm());
      }
    if (children.empty() || reach > 0.5 * length) continue;
    // The parent cut back by that distance (its last stretch runs up the middle of the junction's blob).
    size_t cut = parent.points.size() - 1;
    while (cut > 1 && parent.arcLength[cut] > length - reach) --cut;
    const Eigen::Vector3d junction = parent.points[cut];
    const Eigen::Vector3d along = (parent.points[cut] - parent.points[cut - 1]).normalized();
    parent.points.resize(cut + 1);
    parent.radius.resize(cut + 1);
    parent.arcLength.resize(cut + 1);
    if (!parent.bridged.empty()) parent.bridged.resize(cut + 1);
    // Each child reached from there along a curve leaving the parent's direction and arriving along its own.
    for (size_t c : children) {
      Centerline& child = branches[c];
      const Eigen::Vector3d start = child.points.front();
      const Eigen::Vector3d own = (child.points[2] - child.points[0]).normalized();
      std::vector<Eigen::Vector3d> path =
          hermiteCurve(junction, along, start, own, step, kJunctionTangentScale);
      const std::vector<double> distance = distanceAtPoints(volume, path);
      Centerline joined;
      for (size_t k = 0; k < path.size(); ++k) {
        joined.points.push_back(path[k]);
        joined.radius.push_back(std::max(distance[k] - halfVoxel, halfVoxel));
        joined.arcLength.push_back(joined.points.size() == 1
                                       ? (path[k] - junction).norm()
                                       : joined.arcLength.back() + (path[k] - path[k - 1]).norm());
      }
      const double offset = (joined.points.empty() ? (start - junction).norm()
                                                   : joined.arcLength.back() + (start - path.back()).norm());
      for (size_t k = 0; k < child.points.size(); ++k) {
        joined.points.push_back(child.points[k]);
        joined.radius.push_back(child.radius[k]);
        joined.arcLength.push_back(offset + child.arcLength[k]);
      }
      if (!child.bridged.empty()) joined.bridged.assign(joined.points.size(), 0);
      child = std::move(joined);
    }
  }
}

}  // namespace medial
