/// \file
/// InsideTest: is a point inside a triangle mesh, and does a segment stay inside it? Ray parity over an
/// AABB tree of the triangles (CGAL), voted over three fixed, generic directions so that a ray grazing an
/// edge or a vertex, or a small hole in an open mesh, does not decide alone.
#pragma once

#include "mesh/TriangleMesh.h"

#include <memory>

namespace medial {

/// Point-in-mesh, ray and distance queries on a triangle mesh (CGAL AABB tree over its triangles).
class InsideTest {
 public:
  /// Builds the tree over `mesh`'s triangles (the mesh is copied).
  explicit InsideTest(const TriangleMesh& mesh);
  ~InsideTest();
  InsideTest(const InsideTest&) = delete;
  InsideTest& operator=(const InsideTest&) = delete;

  /// Whether `point` lies inside the closed mesh (ray parity).
  bool contains(const Eigen::Vector3d& point) const;
  /// For a closed, consistently oriented mesh that may cut itself (overlapping tubes): whether its winding
  /// number at the point is >= 1, i.e. it lies inside at least one of the volumes the surface wraps.
  /// Crossings along a ray are counted +1 through a face seen from behind, -1 from the front.
  bool wrapped(const Eigen::Vector3d& point) const;
  /// True when the open segment a-b crosses no triangle (its end points may lie on the surface).
  bool segmentIsClear(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  /// Squared distance from `point` to the nearest triangle.
  double squaredDistanceToSurface(const Eigen::Vector3d& point) const;
  /// Distance from origin along the unit direction to the first triangle the ray meets; infinity if none.
  double distanceAlongRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) const;
  /// The nearest point of the surface (the point itself for an empty mesh).
  Eigen::Vector3d closestSurfacePoint(const Eigen::Vector3d& point) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace medial
