// SqmMesh: the polygon mesh SQM makes (quads and triangles) with the skeleton node of each vertex.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace medial {

struct SqmMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;  // quads and triangles, outward oriented
  std::vector<int> vertexNode;          // the skeleton node each vertex belongs to (-1: a capsule node)
  int quadCount() const;
  int triangleCount() const;
  // The node most vertices of face f belong to (ties: the smallest).
  int faceNode(size_t f) const;
};

}  // namespace medial
