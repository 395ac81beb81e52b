#include "sqm/CycleClosing.h"

#include "sqm/RingAngles.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace medial {

namespace {

// Joins ring A (angles increasing along it) and ring B (angles decreasing along it) by walking both in
// angular order from their smallest angles: one triangle per step, |A| + |B| triangles.
std::vector<std::array<int, 3>> zipByAngle(const std::vector<int>& ringA, const std::vector<double>& angleA,
                                           const std::vector<int>& ringB, const std::vector<double>& angleB) {
  const int m = int(ringA.size()), n = int(ringB.size());
  std::vector<int> b(ringB.rbegin(), ringB.rend());  // increasing angles
  std::vector<double> bAngle(angleB.rbegin(), angleB.rend());
  // Monotone angles, or the walk can run round one ring before the other moves (a pinched band).
  std::vector<double> aAngle = angleA;
  untangleAngles(aAngle, +1);
  untangleAngles(bAngle, +1);
  for (double& a : aAngle) a = std::remainder(a, 2 * M_PI);
  for (double& a : bAngle) a = std::remainder(a, 2 * M_PI);
  const int a0 = int(std::min_element(aAngle.begin(), aAngle.end()) - aAngle.begin());
  const int b0 = int(std::min_element(bAngle.begin(), bAngle.end()) - bAngle.begin());
  auto unwrapped = [](const std::vector<double>& angles, int start, int k) {
    const int size = int(angles.size());
    double value = angles[size_t((start + k) % size)];
    while (value < angles[size_t(start)]) value += 2 * M_PI;
    return value + (k >= size ? 2 * M_PI * (k / size) : 0.0);
  };
  std::vector<std::array<int, 3>> triangles;
  int i = 0, j = 0;
  while (i < m || j < n) {
    const int ai = ringA[size_t((a0 + i) % m)], bj = b[size_t((b0 + j) % n)];
    const bool advanceA = j == n || (i < m && unwrapped(aAngle, a0, i + 1) <= unwrapped(bAngle, b0, j + 1));
    if (advanceA) {
      triangles.push_back({ai, ringA[size_t((a0 + i + 1) % m)], bj});  // A's edge in its own direction
      ++i;
    } else {
      triangles.push_back({ai, b[size_t((b0 + j + 1) % n)], bj});  // B's edge against the reversed order
      ++j;
    }
  }
  return triangles;
}

}  // namespace

std::vector<std::array<int, 3>> closeCycleGap(const std::vector<Eigen::Vector3d>& positions,
                                              const std::vector<int>& ringA, const Eigen::Vector3d& centreA,
                                              const std::vector<int>& ringB, const Eigen::Vector3d& centreB) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using VertexBase =
      CGAL::Triangulation_vertex_base_with_info_2<std::pair<int, int>, Kernel>;  // (ring, vertex)
  using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<VertexBase>>;

  // The plane across the cut: (e1, e2, d) right-handed, so ring A (counter-clockwise about d) turns
  // counter-clockwise in the plane and ring B (counter-clockwise about -d) clockwise.
  Eigen::Vector3d d = centreB - centreA;
  if (d.squaredNorm() == 0) d = Eigen::Vector3d::UnitZ();
  d.normalize();
  const Eigen::Vector3d e1 =
      (std::abs(d.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY()).cross(d).normalized();
  const Eigen::Vector3d e2 = d.cross(e1);
  std::vector<std::pair<Kernel::Point_2, std::pair<int, int>>> points;
  auto addRing = [&](const std::vector<int>& ring, const Eigen::Vector3d& centre, int which, double radius) {
    for (size_t k = 0; k < ring.size(); ++k) {
      const Eigen::Vector3d offset = positions[size_t(ring[k])] - centre;
      const double angle = std::atan2(offset.dot(e2), offset.dot(e1));
      points.push_back(
          {Kernel::Point_2(radius * std::cos(angle), radius * std::sin(angle)), {which, int(k)}});
    }
  };
  addRing(ringA, centreA, 0, 1.0);
  addRing(ringB, centreB, 1, 2.0);
  const Delaunay triangulation(points.begin(), points.end());

  std::vector<std::array<int, 3>> triangles;
  bool chord = false;  // a triangle whose two corners on one ring are not neighbours along it
  std::vector<double> angleA, angleB;
  for (const auto& [point, info] : points)
    (info.first == 0 ? angleA : angleB).push_back(std::atan2(point.y(), point.x()));
  for (auto face = triangulation.finite_faces_begin(); face != triangulation.finite_faces_end(); ++face) {
    std::array<std::pair<int, int>, 3> corner;
    for (int c = 0; c < 3; ++c) corner[size_t(c)] = face->vertex(c)->info();
    const int fromA = (corner[0].first == 0) + (corner[1].first == 0) + (corner[2].first == 0);
    if (fromA == 0 || fromA == 3) continue;  // inside one ring: the paper drops these
    auto id = [&](const std::pair<int, int>& c) {
      return c.first == 0 ? ringA[size_t(c.second)] : ringB[size_t(c.second)];
    };
    for (int c = 0; c < 3; ++c) {
      const auto& p = corner[size_t(c)];
      const auto& q = corner[size_t((c + 1) % 3)];
      const int size = int(p.first == 0 ? ringA.size() : ringB.size());
      if (p.first == q.first && (p.second - q.second + size) % size != 1 &&
          (q.second - p.second + size) % size != 1)
        chord = true;
    }
    // Delaunay faces are counter-clockwise in the plane; the band needs them the other way round.
    triangles.push_back({id(corner[0]), id(corner[2]), id(corner[1])});
  }
  // A closed band has one triangle per ring edge. When a ring is lopsided (all its vertices on one side of
  // its centre, as a pillow's one-ring can be) the Delaunay triangulation does not wrap around the
  // annulus, and when a ring does not turn monotonically in this plane a triangle spans a chord of it
  // (a non-manifold band); the rings are then zipped by angle instead.
  if (chord || triangles.size() != ringA.size() + ringB.size())
    triangles = zipByAngle(ringA, angleA, ringB, angleB);
  return triangles;
}

}  // namespace medial
