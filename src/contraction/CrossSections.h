/// \file
/// CrossSections: where a skeleton point sits in the mesh's cross-section through it, and the centring
/// measure built on that (issue 26): cut the mesh with the plane through a point normal to the skeleton's
/// direction there; among the closed cut loops that wind around the point, the one of smallest area A is
/// the point's cross-section; the point's off-centre ratio is its distance to that loop's area centroid
/// divided by sqrt(A / pi) (0 on the axis of a round tube, 1 on its wall). CGAL's Polygon_mesh_slicer cuts.
#pragma once

#include "mesh/TriangleMesh.h"
#include "skeleton/Skeleton.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace medial {

/// A closed loop of a mesh's cut by a plane, around a point (CrossSections::around()).
struct CrossSection {
  bool found = false;  ///< false: no closed loop winds around the point (it is outside, or the cut is open)
  double area = 0;     ///< the area the loop encloses
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();    ///< the centroid of that area
  double offCentre(const Eigen::Vector3d& point) const;  ///< |point - centroid| / sqrt(area / pi)
};

/// Plane cuts of a mesh, for the centring of skeleton nodes and its measure.
class CrossSections {
 public:
  /// Indexes `mesh`'s triangles for plane cuts.
  explicit CrossSections(const TriangleMesh& mesh);
  ~CrossSections();
  CrossSections(const CrossSections&) = delete;
  CrossSections& operator=(const CrossSections&) = delete;

  /// The smallest closed loop of the cut by the plane through `point` normal to `normal` that winds around
  /// `point`.
  CrossSection around(const Eigen::Vector3d& point, const Eigen::Vector3d& normal) const;

 private:
  struct Slicer;
  std::unique_ptr<Slicer> slicer_;
};

/// The measure over a skeleton: `samples` points on its edges (edges drawn with probability
/// proportional to their length, a uniform position in the middle 60 % of the edge, a fixed seed), each
/// with its off-centre ratio; points with no loop around them are counted apart (outside).
struct OffCentreSummary {
  std::vector<double> ratios;           ///< of the points with a cross-section
  std::vector<Eigen::Vector3d> points;  ///< those points, in the order of `ratios`
  int outside = 0;                      ///< sample points with no loop around them
  /// The median of `ratios` (NaN when empty).
  double median() const;
  /// The 90th percentile of `ratios` (NaN when empty).
  double percentile90() const;
};
/// The off-centre ratios of `samples` points on `skeleton`'s edges (see OffCentreSummary), drawn
/// with `seed`.
OffCentreSummary offCentre(const Skeleton& skeleton, const CrossSections& sections, int samples = 150,
                           unsigned seed = 1);

}  // namespace medial
