#include "rig/SkinBinding.h"

#include "common/UnionFind.h"
#include "mesh/InsideTest.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace medial {

namespace {

using Neighbours = std::vector<std::vector<std::pair<int, double>>>;  // (node, edge length) per node

Neighbours neighbours(const Skeleton& skeleton) {
  Neighbours around(size_t(skeleton.nodeCount()));
  for (const auto& e : skeleton.edges) {
    const double length = (skeleton.nodes[size_t(e[0])] - skeleton.nodes[size_t(e[1])]).norm();
    around[size_t(e[0])].emplace_back(e[1], length);
    around[size_t(e[1])].emplace_back(e[0], length);
  }
  return around;
}

// Distances along the edges from `source` (Dijkstra) and each node's predecessor on its shortest path.
void shortestPaths(const Neighbours& around, int source, std::vector<double>& distance,
                   std::vector<int>& previous) {
  distance.assign(around.size(), INFINITY);
  previous.assign(around.size(), -1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  distance[size_t(source)] = 0;
  queue.emplace(0.0, source);
  while (!queue.empty()) {
    const auto [d, node] = queue.top();
    queue.pop();
    if (d > distance[size_t(node)]) continue;
    for (const auto& [next, length] : around[size_t(node)])
      if (d + length < distance[size_t(next)]) {
        distance[size_t(next)] = d + length;
        previous[size_t(next)] = node;
        queue.emplace(d + length, next);
      }
  }
}

int farthest(const std::vector<double>& distance) {
  int best = -1;
  for (size_t i = 0; i < distance.size(); ++i)
    if (std::isfinite(distance[i]) && (best < 0 || distance[i] > distance[size_t(best)])) best = int(i);
  return best;
}

// A node of the component with the largest total edge length (node 0 when there are no edges).
int nodeOfLongestComponent(const Skeleton& skeleton) {
  UnionFind components(size_t(skeleton.nodeCount()));
  for (const auto& e : skeleton.edges) components.join(e[0], e[1]);
  std::vector<double> length(size_t(skeleton.nodeCount()), 0.0);
  int best = 0;
  for (const auto& e : skeleton.edges) {
    const int c = components.find(e[0]);
    length[size_t(c)] += (skeleton.nodes[size_t(e[0])] - skeleton.nodes[size_t(e[1])]).norm();
    if (length[size_t(c)] > length[size_t(best)]) best = c;
  }
  return best;
}

bool boxesOverlap(const TriangleMesh& mesh, const Skeleton& skeleton) {
  Eigen::Vector3d skeletonMin = Eigen::Vector3d::Constant(INFINITY), skeletonMax = -skeletonMin;
  for (const Eigen::Vector3d& p : skeleton.nodes) {
    skeletonMin = skeletonMin.cwiseMin(p);
    skeletonMax = skeletonMax.cwiseMax(p);
  }
  const Eigen::Vector3d meshMin = mesh.vertices.colwise().minCoeff().transpose();
  const Eigen::Vector3d meshMax = mesh.vertices.colwise().maxCoeff().transpose();
  return (skeletonMin.array() <= meshMax.array()).all() && (meshMin.array() <= skeletonMax.array()).all();
}

}  // namespace

int centralNode(const Skeleton& skeleton) {
  if (skeleton.nodeCount() == 0) return -1;
  const Neighbours around = neighbours(skeleton);
  std::vector<double> distance;
  std::vector<int> previous;
  // Two sweeps find the ends of the longest path (exactly on a tree, nearly so with cycles).
  shortestPaths(around, nodeOfLongestComponent(skeleton), distance, previous);
  const int end = farthest(distance);
  shortestPaths(around, end, distance, previous);
  int node = farthest(distance);
  const double half = distance[size_t(node)] / 2;
  int best = node;
  for (; node >= 0; node = previous[size_t(node)])
    if (std::abs(distance[size_t(node)] - half) < std::abs(distance[size_t(best)] - half)) best = node;
  return best;
}

SkinBindingResult bindSkin(const TriangleMesh& mesh, const Skeleton& skeleton,
                           const HeatWeightParameters& parameters,
                           const std::function<bool(double)>& progress) {
  SkinBindingResult result;
  if (mesh.faces.rows() == 0) {
    result.error = "the mesh has no faces to bind";
    return result;
  }
  if (skeleton.edgeCount() == 0) {
    result.error = "the skeleton has no edges (bones)";
    return result;
  }
  if (!boxesOverlap(mesh, skeleton)) {
    result.error = "the skeleton lies outside the mesh's bounding box (another unit or coordinate frame?)";
    return result;
  }
  result.root = skeleton.root >= 0 ? skeleton.root : centralNode(skeleton);
  const InsideTest inside(mesh);
  for (const Eigen::Vector3d& p : skeleton.nodes)
    if (!inside.contains(p)) ++result.nodesOutside;
  HeatWeightResult heat = heatWeights(mesh, skeleton, inside, parameters, progress);
  if (!heat.ok()) {
    result.error = heat.error;
    return result;
  }
  result.weights = std::move(heat.weights);
  result.invisibleVertices = heat.invisibleVertices;
  return result;
}

}  // namespace medial
