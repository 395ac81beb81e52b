/// \file
/// FoldRepair: the refinement's fold repair (beyond the CESCG 2014 paper; SqmRefinement runs it on each
/// refined level). The projection onto the swept surfaces can fold the refined surface where tubes of
/// different edges crowd (a thin tube leaving a flat ellipsoid, a right-angle bend), while the base mesh's
/// faces tessellated without projection ("flat") lie on the base mesh, which does not cut itself there. Each
/// vertex of a face that folds over another goes back halfway from its projection towards its flat point,
/// as often as needed (at most kFoldRepairSteps times, then all the way); every other vertex stays on its
/// surface. A fold of the base mesh itself (two faces almost coplanar across a sharp vertex, once on the
/// hand sample) shows once its quads are split: the vertices still folded then move to the centroid of
/// their neighbours, a few times.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <utility>
#include <vector>

namespace medial {

/// Of two faces of the level that cut each other: whether they are a fold to undo (FoldPairs), not tubes
/// of other parts overlapping, which no move back towards the base mesh undoes.
using IsFold = std::function<bool(int, int)>;

/// What the fold repair of one refinement level did.
struct FoldRepairResult {
  int movedVertices = 0;  ///< refined vertices moved back towards the base mesh
  bool settled = false;   ///< no fold left
  /// Folds left, and some of them do not cut each other on the flat tessellation: repairing the coarser
  /// levels as well may undo them. False when every fold left is one of the base mesh itself.
  bool repairable = false;
  std::vector<std::pair<int, int>> foldsLeft;  ///< the pairs of faces still folded
  /// Per vertex, the share of its move from `flat` to the given point that it kept: 1 where it did not
  /// move, 0 back on the base mesh's tessellation (or smoothed there).
  std::vector<double> shares;
};

/// Moves `points` (the projected vertices of `faces`; `flat` where they lie on the base mesh's tessellation)
/// until no pair of the faces, of which `candidates` are those that can fold at all, is a fold.
FoldRepairResult repairFolds(const std::vector<std::vector<int>>& faces,
                             const std::vector<Eigen::Vector3d>& flat, std::vector<Eigen::Vector3d>& points,
                             const IsFold& isFold, std::vector<int> candidates);

}  // namespace medial
