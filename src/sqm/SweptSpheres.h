/// \file
/// SweptSpheres: the surface SQM's refinement projects onto, the union of the spheres swept along the
/// skeleton's edges (the CESCG 2014 paper, section 5: each edge sweeps a sphere whose radius runs linearly
/// from one node's to the other's, so its surface is the two end spheres joined by the cone tangent to
/// both). A point near an edge goes onto that edge's swept surface along the surface normal: radially from
/// the end sphere's centre beyond the cone's tangent circles - this is what keeps the outer side of a
/// corner on the node's sphere - and along the cone's normal between them.
/// With ellipsoid nodes (extension 3) the cross-section interpolates the two ends' ellipsoid matrices and
/// the point moves radially from the axis (no closed form for the tangent surface of two ellipsoids).
#pragma once

#include "skeleton/Skeleton.h"

#include <Eigen/Core>

#include <vector>

namespace medial {

/// Where a point goes on one edge's swept surface: centre + radius * direction. `distance` is the point's
/// distance from `centre` along `direction`: distance - radius is its signed distance to the surface.
struct SweptPoint {
  Eigen::Vector3d centre;     ///< the nearest point on the edge's axis
  Eigen::Vector3d direction;  ///< unit direction from centre towards the point
  double radius = 0;          ///< the swept radius there
  double distance = 0;        ///< the point's distance from centre
  bool found = false;         ///< false on the axis itself, where the direction is undefined
  /// The point's projection: centre + radius * direction.
  Eigen::Vector3d onSurface() const { return centre + radius * direction; }
  /// Distance to the swept surface: negative inside.
  double signedDistance() const { return distance - radius; }
};

/// The surfaces swept by the skeleton's spheres along its edges (SQM stage 8's projection target),
/// with an index of the edges' bounding boxes.
class SweptSpheres {
 public:
  /// Indexes every edge of `skeleton` (radii per node).
  explicit SweptSpheres(const Skeleton& skeleton);

  /// The projection of `p` onto the swept surface of edge `edge`.
  SweptPoint project(const Eigen::Vector3d& p, int edge) const;
  /// Edges whose swept volume comes within `margin` of the box [low, high] (an AABB test).
  std::vector<int> edgesNear(const Eigen::Vector3d& low, const Eigen::Vector3d& high, double margin) const;
  /// Signed distance to the union over all edges (negative inside), exact outside the union.
  double signedDistance(const Eigen::Vector3d& p) const;
  /// The skeleton indexed (kept by reference).
  const Skeleton& skeleton() const { return skeleton_; }

 private:
  const Skeleton& skeleton_;
  std::vector<Eigen::Vector3d> low_, high_;  ///< each edge's swept box
};

}  // namespace medial
