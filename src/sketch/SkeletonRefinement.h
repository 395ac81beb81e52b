/// \file
/// SkeletonRefinement: the subpart- and global-level operations of the sketch skeletonization (Ma et al.
/// 2021, §3.3), each controlled by a distance threshold given per node (so that one part can carry its own
/// thresholds and the rest the global ones). Each returns the number of joints it removed; a larger
/// threshold never removes fewer.
///
///  - mergeJunctions (epsilon_m, default 30): junction joints (degree >= 3) whose path along the bones is
///    at most the threshold (the smaller of the two ends') are clustered by a breadth-first search; each
///    cluster and the joints on its paths become one junction at the junctions' centroid with their largest
///    radius (Fig. 11). Path length rather than straight distance keeps the skeleton a tree.
///  - pruneBranches (epsilon_t, default 30): a JT-branch (junction to terminal) shorter than its terminal's
///    threshold is removed, shortest first, as long as its junction keeps a bone, so that pruning never
///    cuts a skeleton down to nothing. A branch's length is how far it reaches beyond its junction's ball:
///    bone lengths + terminal radius - junction radius (the paper leaves "length" open). For a limb that is
///    about its visible length; for the spur the medial axis sends into a rounded corner of a part of
///    half-width R it is at most 0.41 R. Whatever the drawing's scale, a branch reaching less than half its
///    junction's radius beyond the ball is such a spur and is removed too: hand-drawn corners (and the
///    resampling's rounding of sharp ones) do not grow fingers, and a rectangle stays one bone.
///  - collapseEdges (epsilon_c, default 10): a bone between two internal joints (degree >= 2) shorter than
///    the threshold is collapsed, shortest first; the joint goes to the junction when one end is a junction,
///    to the midpoint otherwise.
#pragma once

#include "sketch/SketchGraph.h"

namespace medial {

///@{
/// The three operations of the file's description; each returns the joints it removed.
int mergeJunctions(SketchGraph& graph, const std::vector<double>& threshold);
int pruneBranches(SketchGraph& graph, const std::vector<double>& threshold);
int collapseEdges(SketchGraph& graph, const std::vector<double>& threshold);
///@}

}  // namespace medial
