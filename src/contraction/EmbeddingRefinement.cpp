#include "contraction/EmbeddingRefinement.h"

#include <vector>

namespace medial {

int refineEmbedding(CurveSkeleton& skeleton, const Vertices& originalVertices, const InsideTest& inside) {
  const Eigen::Index nodeCount = skeleton.nodes.rows();
  Vertices sum = Vertices::Zero(nodeCount, 3);
  std::vector<int> count(size_t(nodeCount), 0);
  for (size_t v = 0; v < skeleton.vertexToNode.size(); ++v) {
    const int node = skeleton.vertexToNode[v];
    if (node < 0) continue;
    sum.row(node) += originalVertices.row(Eigen::Index(v));
    ++count[size_t(node)];
  }
  int moved = 0;
  for (Eigen::Index k = 0; k < nodeCount; ++k) {
    if (count[size_t(k)] == 0) continue;
    const Eigen::Vector3d centroid = (sum.row(k) / count[size_t(k)]).transpose();  // v_k + d_k, eq. (11)
    // A centroid of one or two surface vertices lies on the surface, not inside.
    if (count[size_t(k)] < 3 || !inside.contains(centroid)) continue;
    skeleton.nodes.row(k) = centroid.transpose();
    ++moved;
  }
  return moved;
}

}  // namespace medial
