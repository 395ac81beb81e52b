/// \file
/// NodeSelection: section III.D of the contraction paper. Reduces the refined curve skeleton to about
/// `targetNodes` nodes (the paper: 20 to 40 for animation) by collapsing the shortest edges first, the cost
/// of eq. (12) F(i, j) = |v_i - v_j|.
///
/// What the paper leaves open, chosen here: the skeleton stays connected and keeps its cycles. An edge is
/// not collapsed when its two ends share a neighbour (the collapse would fold a cycle into a double edge)
/// or when both ends are leaves (a segment on its own). The merged node keeps the position of the more
/// significant end (leaf, then branch node, then connection node) or the midpoint of two equal ends, so
/// tips and junctions stay where they are; a leaf on a branch node merges into the branch node, so side
/// branches go shortest first. With an InsideTest, a collapse whose new edges would leave the mesh is
/// refused (a bent limb keeps the node at its bend) unless the merged node can sit at either end instead.
/// The count may stay above the target when no edge can be collapsed.
#pragma once

#include "contraction/ConnectivitySurgery.h"
#include "mesh/InsideTest.h"

#include <vector>

namespace medial {

/// Returns the number of collapses; vertexToNode is renumbered to the surviving nodes. cameFrom, when
/// given, receives for each surviving node its index before the selection (the node that absorbed the
/// others; it may have moved to the middle of a collapsed edge).
int selectNodes(CurveSkeleton& skeleton, int targetNodes, const InsideTest* inside = nullptr,
                std::vector<int>* cameFrom = nullptr);

}  // namespace medial
