/// \file
/// SketchGraph: the 3-D skeleton of a sketch while it is connected and refined (Ma et al. 2021, §3.2-3.3),
/// a medial::Skeleton whose nodes and edges remember the part (stroke) they came from and whose edges
/// remember their branch in that part's local skeleton (-1 for bones made by connecting parts).
#pragma once

#include "skeleton/Skeleton.h"

#include <vector>

namespace medial {

/// A sketch's skeleton with the part and the branch of every node and edge.
struct SketchGraph {
  Skeleton skeleton;            ///< nodes, radii, edges and root
  std::vector<int> nodePart;    ///< one per node
  std::vector<int> edgePart;    ///< one per edge
  std::vector<int> edgeBranch;  ///< one per edge; -1 for connection bones

  /// Adds a node of `part`; returns its id.
  int addNode(const Eigen::Vector3d& position, double radius, int part);
  /// Adds the edge a-b of `part` and `branch` (-1: a connection bone).
  void addEdge(int a, int b, int part, int branch);
  std::vector<std::vector<int>> adjacency() const;  ///< neighbour node ids
  /// The length of edge `edge`.
  double edgeLength(int edge) const;

  /// Rebuilds the graph after a contraction: target[i] is the new id of node i (-1: deleted), new ids are
  /// 0..count-1; position, radius and part of each new node are given. Edges to deleted nodes, self-loops
  /// and repeated edges go; the rest keep their labels. The root follows its node (or is reset).
  void contract(const std::vector<int>& target, const std::vector<Eigen::Vector3d>& positions,
                const std::vector<double>& radii, const std::vector<int>& parts);
};

}  // namespace medial
