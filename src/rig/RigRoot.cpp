#include "rig/RigRoot.h"

#include "common/UnionFind.h"
#include "mesh/MeshGeometry.h"

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

// The two ends of a longest path of the longest component (two sweeps: exact on a tree, nearly so with
// cycles), with the distances from each.
struct LongestPath {
  int first = -1, last = -1;
  std::vector<double> fromFirst, fromLast;
  std::vector<int> towardsFirst;  // predecessor on the shortest path from `first`
};

LongestPath longestPath(const Skeleton& skeleton) {
  LongestPath path;
  const Neighbours around = neighbours(skeleton);
  std::vector<int> previous;
  shortestPaths(around, nodeOfLongestComponent(skeleton), path.fromFirst, previous);
  path.first = farthest(path.fromFirst);
  shortestPaths(around, path.first, path.fromFirst, path.towardsFirst);
  path.last = farthest(path.fromFirst);
  shortestPaths(around, path.last, path.fromLast, previous);
  return path;
}

}  // namespace

std::vector<double> nodeEccentricities(const Skeleton& skeleton, double& longest) {
  longest = 0;
  if (skeleton.nodeCount() == 0) return {};
  const LongestPath path = longestPath(skeleton);
  longest = path.fromFirst[size_t(path.last)];
  std::vector<double> eccentricity(size_t(skeleton.nodeCount()), INFINITY);
  for (size_t v = 0; v < eccentricity.size(); ++v)
    if (std::isfinite(path.fromFirst[v])) eccentricity[v] = std::max(path.fromFirst[v], path.fromLast[v]);
  return eccentricity;
}

int centralNode(const Skeleton& skeleton) {
  if (skeleton.nodeCount() == 0) return -1;
  const LongestPath path = longestPath(skeleton);
  const double half = path.fromFirst[size_t(path.last)] / 2;
  int best = path.last;
  for (int node = path.last; node >= 0; node = path.towardsFirst[size_t(node)])
    if (std::abs(path.fromFirst[size_t(node)] - half) < std::abs(path.fromFirst[size_t(best)] - half))
      best = node;
  return best;
}

int bodyCentreNode(const Skeleton& skeleton, const TriangleMesh& mesh) {
  const int n = skeleton.nodeCount();
  if (n == 0) return -1;
  double longest = 0;
  const std::vector<double> eccentricity = nodeEccentricities(skeleton, longest);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  if (mesh.faces.rows() > 0) {
    centre = volumeCentroid(mesh.vertices, mesh.faces);
  } else {  // the skeleton's own centre of edge length
    double total = 0;
    for (const auto& e : skeleton.edges) {
      const double length = (skeleton.nodes[size_t(e[0])] - skeleton.nodes[size_t(e[1])]).norm();
      centre += length * (skeleton.nodes[size_t(e[0])] + skeleton.nodes[size_t(e[1])]) / 2;
      total += length;
    }
    centre = total > 0 ? Eigen::Vector3d(centre / total) : skeleton.nodes[0];
  }
  const std::vector<int> degree = nodeDegrees(skeleton);
  int best = -1;
  bool bestBranches = false;
  double bestDistance = INFINITY;
  for (int v = 0; v < n; ++v) {
    if (!(eccentricity[size_t(v)] <= kCentralShare * longest)) continue;
    const bool branches = degree[size_t(v)] >= 3;
    const double distance = (skeleton.nodes[size_t(v)] - centre).norm();
    if (best < 0 || (branches && !bestBranches) || (branches == bestBranches && distance < bestDistance)) {
      best = v;
      bestBranches = branches;
      bestDistance = distance;
    }
  }
  return best >= 0 ? best : centralNode(skeleton);
}

}  // namespace medial
