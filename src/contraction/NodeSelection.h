// NodeSelection: section III.D of the contraction paper. Reduces the refined curve skeleton to about
// `targetNodes` nodes (the paper: 20 to 40 for animation) by collapsing the shortest edges first, the cost
// of eq. (12) F(i, j) = |v_i - v_j|.
//
// What the paper leaves open, chosen here: a collapse never removes a branch or a cycle. An edge is not
// collapsed when its two ends share a neighbour (the collapse would fold a cycle into a double edge), when
// both ends are leaves (a segment on its own) or when a leaf hangs on a branch node (the branch would go).
// The merged node keeps the position of the more significant end (leaf, then branch node, then connection
// node) or the midpoint of two equal ends, so tips and junctions stay where they are. The count may stay above the target when no edge can be collapsed.
#pragma once

#include "contraction/ConnectivitySurgery.h"

#include <vector>

namespace medial {

// With node radii, a twig (a leaf edge shorter than the radius of its inner node: it ends inside the
// tube of its neighbour, an artefact of the surgery) is collapsed into its inner node like any edge.
// Returns the number of collapses; vertexToNode is renumbered to the surviving nodes.
int selectNodes(CurveSkeleton& skeleton, int targetNodes, const std::vector<double>& radii = {});

}  // namespace medial
