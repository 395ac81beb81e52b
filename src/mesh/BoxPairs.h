/// \file
/// BoxPairs: which axis-aligned boxes of a large set overlap, by a uniform grid of cells about as large as
/// the typical box. CGAL's box_intersection_d (a segment tree) spent 30 of 38 s sorting on the faces of a
/// 180,000-node SQM chain lying along one axis, where many boxes share coordinates; a grid takes time in
/// proportion to the boxes and the pairs found however they are laid out.
#pragma once

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace medial {

/// An axis-aligned box.
struct Box3 {
  Eigen::Vector3d low;   ///< the smallest corner
  Eigen::Vector3d high;  ///< the largest corner
};

/// Pairs (i, j), i < j, of boxes that overlap (touching counts), each once. The order is fixed by the
/// boxes alone (grid cell by grid cell), not sorted. With `selected` (a flag per box), only the pairs with
/// a selected box, in time for the selected boxes' cells (a few moved faces of a large mesh).
std::vector<std::pair<int, int>> overlappingBoxPairs(const std::vector<Box3>& boxes,
                                                     const std::vector<char>* selected = nullptr);

}  // namespace medial
