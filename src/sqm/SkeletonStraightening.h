/// \file
/// SkeletonStraightening: the rooted tree SQM works on and its straightened bind pose (SQM papers: CESCG 2014
/// section 4 "Skeleton straightening" and "Skinning"; thesis chapter, section "Skeleton straightening").
///
/// Tree: one connected, acyclic component of a skeleton, rooted at the requested node when it is a branch
/// node; otherwise re-rooted at the first branch node a depth-first search from it meets (extension 1); a
/// component without branch nodes (a linear skeleton) is rooted at an end (extension 2).
///
/// Straightening: every path between branch nodes and leaves becomes a straight line. Walking from the
/// root, a child of a branch node (or of the root) keeps its offset from its parent (rotated as the parent
/// was), so the angles between a branch node's edges survive; the child of a connection node is put on the
/// line through the connection node's parent and the connection node, at its original distance, and its
/// whole subtree turns with it. `rotation[k]` maps offsets of node k's subtree from the input (reference)
/// pose to the bind pose: bind(k) - bind(parent) = rotation[k] * (p(k) - p(parent)).
#pragma once

#include "skeleton/Skeleton.h"

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace medial {

/// One acyclic component of a skeleton as a rooted tree (see the file's description).
struct SqmTree {
  int root = -1;            ///< the root node
  std::vector<int> nodes;   ///< the component's nodes, depth-first order from the root
  std::vector<int> parent;  ///< per skeleton node; -1 for the root and nodes of other components
  std::vector<std::vector<int>> children;  ///< per skeleton node
  bool hasBranchNode = false;              ///< false: a linear skeleton, rooted at an end (extension 2)
  /// Whether node k has three or more neighbours.
  bool isBranch(int k) const { return neighbourCount(k) >= 3; }
  /// Whether node k has at most one neighbour.
  bool isLeaf(int k) const { return neighbourCount(k) <= 1; }
  /// Node k's neighbours in the tree: its children and its parent.
  int neighbourCount(int k) const {
    return int(children[size_t(k)].size()) + (parent[size_t(k)] >= 0 ? 1 : 0);
  }
  /// The neighbours of k: its parent first (when it has one), then its children.
  std::vector<int> neighbours(int k) const;
};

/// The tree of the component holding `start` (which must have no cycle), rooted as described above.
/// `preferredRoot` is used when it lies in the component.
SqmTree buildSqmTree(const Skeleton& skeleton, int start, int preferredRoot);

/// The straightened skeleton: where each node goes and how its subtree turns.
struct BindPose {
  std::vector<Eigen::Vector3d> position;  ///< bind (straightened) position per skeleton node
  std::vector<Eigen::Quaterniond>
      rotation;  ///< reference -> bind offset rotation per node (identity at root)
};

/// The bind pose of `tree`: every path between branch nodes and leaves made straight (see above).
BindPose straightenSkeleton(const Skeleton& skeleton, const SqmTree& tree);

}  // namespace medial
