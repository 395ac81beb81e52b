/// \file
/// FoldPairs: which skeleton nodes are near each other, and which pairs of refined faces that cut each other
/// are folds the refinement's fold repair should undo (SqmRefinement), and which are tubes of other parts of
/// the skeleton overlapping, which no move back towards the base mesh can undo (they are SqmUnion's work, or
/// a note to the user).
///
/// A pair is a fold when the base faces it was refined from belong to skeleton nodes at most kFoldHops
/// edges apart (a bend, a branch node's crowded arms) and the base mesh's faces of those two nodes did not
/// already cut each other (siblings overlapping beyond their branch node). Without that, a dense tree whose
/// branches pass through others has thousands of refined vertices pulled off their tubes, for nothing.
#pragma once

#include "skeleton/Skeleton.h"
#include "sqm/SqmMesh.h"

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

namespace medial {

/// Which faces cutting each other after refinement are folds of one tube (to repair) rather than
/// tubes of different parts overlapping (left to the union): decided from the base faces' skeleton nodes.
class FoldPairs {
 public:
  /// `base`: the mesh before refinement, its vertexNode indexing `skeleton`'s nodes.
  FoldPairs(const SqmMesh& base, const Skeleton& skeleton);
  /// Whether two faces refined from base faces a and b that cut each other are a fold.
  bool isFold(int baseFaceA, int baseFaceB) const;
  /// Whether nodes a and b are at most kFoldHops edges apart (a face refines onto the swept surfaces of
  /// the edges near its node only: a tube of another part passing through is not its surface).
  bool near(int a, int b) const { return near_.count({std::min(a, b), std::max(a, b)}) > 0; }
  /// The node of a base face (SqmMesh::faceNode).
  int faceNode(int baseFace) const { return faceNode_[size_t(baseFace)]; }
  /// The number of pairs of nodes whose base faces already cut each other.
  int baseOverlaps() const { return int(baseOverlaps_.size()); }

 private:
  std::vector<int> faceNode_;
  std::set<std::pair<int, int>> near_;          ///< node pairs within kFoldHops edges, first <= second
  std::set<std::pair<int, int>> baseOverlaps_;  ///< node pairs whose base faces cut each other
  /// Per node a, the nodes b >= a of its pairs that are folds (near, not overlapping on the base mesh),
  /// sorted: isFold runs for every pair of refined faces whose boxes overlap (450,000 on the dense tree).
  std::vector<std::vector<int>> foldPartners_;
};

}  // namespace medial
