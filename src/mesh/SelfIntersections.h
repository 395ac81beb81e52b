/// \file
/// SelfIntersections: which faces of a polygon mesh cut through each other, by CGAL's self-intersection
/// test with exact predicates (with plain doubles the coplanar neighbours of a planar quad strip come out
/// as intersecting by rounding). Polygons are split into triangles fanned from their first vertex, as
/// VTK draws them; faces sharing a vertex or an edge intersect only if they overlap beyond it.
#pragma once

#include <Eigen/Core>

#include <cstdint>

#include <utility>
#include <vector>

namespace medial {

/// Pairs of polygon indices (first < second) whose triangles intersect; a pair is listed once however
/// many of its triangles meet. Triangles of one polygon are not tested against each other.
/// \param vertices the mesh's points
/// \param faces polygons as vertex indices (int or int64_t, e.g. from a VTK mesh)
template <class Index>
std::vector<std::pair<int, int>> selfIntersectingFaces(const std::vector<Eigen::Vector3d>& vertices,
                                                       const std::vector<std::vector<Index>>& faces);

}  // namespace medial
