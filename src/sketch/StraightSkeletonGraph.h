/// \file
/// StraightSkeletonGraph: stage 2 of the sketch skeletonization (Ma et al. 2021, §3.1 "Straight skeleton
/// extraction" and "Straight-skeleton simplification"): CGAL's interior straight skeleton [46] of a simple
/// counter-clockwise polygon, reduced to the graph an animator wants.
///
/// Peripheral edges (bisectors that touch a polygon vertex, Fig. 6) are removed, keeping only skeleton
/// edges between skeleton vertices (except at sharp tips, whose bisector is the arm: it is kept, shortened
/// by a third); then every skeleton edge shorter than collapseRatio x the mean
/// skeleton edge length (the paper's 0.5) is collapsed, shortest first; a merged cluster sits at its most
/// central node (largest offset time). The result is a tree (the straight skeleton of a simple polygon is
/// one).
#pragma once

#include "sketch/SketchStroke.h"

#include <array>
#include <string>
#include <vector>

namespace medial {

/// A plane graph: the straight skeleton's nodes and edges.
struct SkeletonGraph2 {
  std::vector<Eigen::Vector2d> nodes;     ///< positions in the stroke's plane
  std::vector<std::array<int, 2>> edges;  ///< node id pairs
  /// The number of nodes.
  int nodeCount() const { return int(nodes.size()); }
};

/// How CGAL's skeleton is computed. automatic: in double arithmetic, kept when it passes a geometric check
/// (every skeleton vertex inside the polygon at its offset time from its faces' contour lines), else again
/// with exact predicates (CGAL's Epick); several times faster than exactPredicates on the sample strokes.
enum class SkeletonArithmetic { automatic, exactPredicates };

/// False with `error` set when CGAL cannot build the skeleton (a degenerate polygon).
bool straightSkeletonGraph(const Polygon2& polygon, double collapseRatio, SkeletonGraph2& graph,
                           std::string& error, SkeletonArithmetic arithmetic = SkeletonArithmetic::automatic);

/// CGAL's straight skeleton alone, for the benchmark's peer: returns its number of skeleton vertices
/// (-1 on failure).
int cgalStraightSkeletonVertexCount(const Polygon2& polygon);

/// Branches (Definition 6): maximal paths whose inner nodes have degree 2, each from a junction or
/// terminal joint to a junction or terminal joint, as node sequences. A lone node is no branch.
/// A cycle made only of degree-2 nodes is returned once, starting and ending at the same node.
std::vector<std::vector<int>> findBranches(int nodeCount, const std::vector<std::array<int, 2>>& edges);

}  // namespace medial
