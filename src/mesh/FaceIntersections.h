/// \file
/// FaceIntersections: which polygons of a mesh cut through each other, found fast enough for a million
/// faces and stopped after a limit. CGAL's `self_intersections` (SelfIntersections.h) builds a halfedge
/// mesh and tests the pairs one after the other: on a 180,000-node SQM chain it took 75 s where the mesh
/// took 2 s. Here the polygons' bounding boxes are paired by CGAL's box intersection and the pairs are
/// tested on every core with the same exact predicates and the same rule for triangles that share a vertex
/// or an edge; tests/src/FaceIntersections_test.cpp holds the two to the same pairs.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace medial {

/// The polygons of a mesh that cut each other (intersectingFaces()).
struct FaceIntersections {
  std::vector<std::pair<int, int>> facePairs;  ///< polygon indices, first < second, sorted
  bool complete = true;                        ///< false: the search stopped at the limit
};

///@{
/// Pairs of polygons whose triangles (fanned from each polygon's first vertex) cut each other beyond the
/// vertices or the edge they share; triangles of one polygon are not tested against each other, nor
/// degenerate ones (a vertex repeated). The result is the same on any number of cores: pairs are tested
/// in a fixed order, and past `limit` pairs the search stops (FaceIntersections::complete is false) with
/// the first `limit` of that order. With `consider`, only the pairs of polygons (indices into `faces`)
/// for which it returns true are tested; it is called from several threads at once. With `selected` (a
/// flag per face), only the pairs with a selected face, in time for the selected faces. With `subset`
/// (indices into `faces`), only the pairs of those faces, in time for the subset (the fold repair tests a
/// few thousand faces of a level of 100,000 at each step); indices stay those of `faces` throughout.
using FacePairFilter = std::function<bool(int, int)>;
FaceIntersections intersectingFaces(const std::vector<Eigen::Vector3d>& vertices,
                                    const std::vector<std::vector<int>>& faces,
                                    size_t limit = std::numeric_limits<size_t>::max(),
                                    const FacePairFilter& consider = {},
                                    const std::vector<char>* selected = nullptr,
                                    const std::vector<int>* subset = nullptr);
///@}

}  // namespace medial
