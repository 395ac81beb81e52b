#include "contraction/EmbeddingRefinement.h"

#include <algorithm>
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

int splitEdgesLeavingTheMesh(CurveSkeleton& skeleton, const Vertices& originalVertices, const InsideTest& inside,
                             int maxDepth) {
  std::vector<std::vector<int>> absorbed(size_t(skeleton.nodes.rows()));
  for (size_t v = 0; v < skeleton.vertexToNode.size(); ++v)
    if (skeleton.vertexToNode[v] >= 0) absorbed[size_t(skeleton.vertexToNode[v])].push_back(int(v));
  struct Pending {
    int a, b, depth;
  };
  std::vector<Pending> pending;
  for (const auto& [a, b] : skeleton.edges) pending.push_back({a, b, 0});
  std::vector<std::pair<int, int>> edges;
  std::vector<Eigen::Vector3d> added;
  auto position = [&](int k) -> Eigen::Vector3d {
    return k < skeleton.nodes.rows() ? Eigen::Vector3d(skeleton.nodes.row(k).transpose()) : added[size_t(k - skeleton.nodes.rows())];
  };
  while (!pending.empty()) {
    const Pending e = pending.back();
    pending.pop_back();
    const Eigen::Vector3d pa = position(e.a), pb = position(e.b), ab = pb - pa;
    if (e.depth >= maxDepth || ab.squaredNorm() == 0 || inside.segmentIsClear(pa, pb)) {
      edges.emplace_back(e.a, e.b);
      continue;
    }
    std::vector<int> middle;  // absorbed vertices of both ends over the middle half of the edge
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int end : {e.a, e.b})
      for (int v : absorbed[size_t(end)]) {
        const Eigen::Vector3d p = originalVertices.row(v).transpose();
        const double t = (p - pa).dot(ab) / ab.squaredNorm();
        if (t < 0.25 || t > 0.75) continue;
        middle.push_back(v);
        sum += p;
      }
    const Eigen::Vector3d centroid = middle.empty() ? pa : Eigen::Vector3d(sum / double(middle.size()));
    if (middle.size() < 3 || !inside.contains(centroid)) {
      edges.emplace_back(e.a, e.b);
      continue;
    }
    const int k = int(skeleton.nodes.rows() + Eigen::Index(added.size()));
    added.push_back(centroid);
    absorbed.emplace_back(middle);
    for (int end : {e.a, e.b}) {
      auto& list = absorbed[size_t(end)];
      list.erase(std::remove_if(list.begin(), list.end(),
                                [&](int v) { return std::find(middle.begin(), middle.end(), v) != middle.end(); }),
                 list.end());
    }
    pending.push_back({e.a, k, e.depth + 1});
    pending.push_back({k, e.b, e.depth + 1});
  }
  if (added.empty()) return 0;
  const Eigen::Index first = skeleton.nodes.rows();
  skeleton.nodes.conservativeResize(first + Eigen::Index(added.size()), 3);
  for (size_t k = 0; k < added.size(); ++k) skeleton.nodes.row(first + Eigen::Index(k)) = added[k].transpose();
  skeleton.edges = std::move(edges);
  for (size_t node = 0; node < absorbed.size(); ++node)
    for (int v : absorbed[node]) skeleton.vertexToNode[size_t(v)] = int(node);
  return int(added.size());
}

}  // namespace medial
