/// \file
/// SqmMesh: the polygon mesh SQM makes (quads and triangles) with the skeleton node of each vertex.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace medial {

/// A polygon mesh of SQM: quads and triangles, each vertex tied to a skeleton node.
struct SqmMesh {
  std::vector<Eigen::Vector3d> vertices;  ///< positions
  std::vector<std::vector<int>> faces;    ///< quads and triangles, outward oriented
  std::vector<int> vertexNode;            ///< the skeleton node each vertex belongs to (-1: a capsule node)
  /// The number of faces with four vertices.
  int quadCount() const;
  /// The number of faces with three vertices.
  int triangleCount() const;
  /// The node most vertices of face f belong to (ties: the smallest).
  int faceNode(size_t f) const;
};

}  // namespace medial
