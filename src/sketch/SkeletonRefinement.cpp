#include "sketch/SkeletonRefinement.h"

#include "sketch/StraightSkeletonGraph.h"

#include "common/UnionFind.h"

#include <algorithm>
#include <numeric>

namespace medial {
namespace {

// Contracts the groups of `groups` (deleted nodes excluded): each group becomes one node at
// `position[root]` with radius `radius[root]`. Returns the number of nodes removed.
int contractGroups(SketchGraph& graph, UnionFind& groups, const std::vector<char>& deleted,
                   const std::vector<Eigen::Vector3d>& position, const std::vector<double>& radius) {
  const int n = graph.skeleton.nodeCount();
  std::vector<int> target(n, -1), newOfRoot(n, -1);
  std::vector<Eigen::Vector3d> positions;
  std::vector<double> radii;
  std::vector<int> parts;
  for (int i = 0; i < n; ++i) {
    if (deleted[i]) continue;
    const int root = groups.find(i);
    if (newOfRoot[root] < 0) {
      newOfRoot[root] = int(positions.size());
      positions.push_back(position[root]);
      radii.push_back(radius[root]);
      parts.push_back(graph.nodePart[root]);
    }
    target[i] = newOfRoot[root];
  }
  const int removed = n - int(positions.size());
  if (removed > 0) graph.contract(target, positions, radii, parts);
  return removed;
}

}  // namespace

int mergeJunctions(SketchGraph& graph, const std::vector<double>& threshold) {
  const int n = graph.skeleton.nodeCount();
  const auto neighbours = graph.adjacency();
  auto isJunction = [&](int v) { return neighbours[v].size() >= 3; };
  UnionFind groups{size_t(n)};
  std::vector<char> merged(n, 0);
  // From each junction, a search along the bones up to its threshold (the tree has one path per pair).
  std::vector<double> distance(n, -1);
  std::vector<int> via(n, -1), visited;
  for (int j = 0; j < n; ++j) {
    if (!isJunction(j)) continue;
    visited.assign(1, j);
    distance[j] = 0;
    for (size_t k = 0; k < visited.size(); ++k) {
      const int v = visited[k];
      for (int w : neighbours[v]) {
        if (distance[w] >= 0) continue;
        const double d = distance[v] + (graph.skeleton.nodes[v] - graph.skeleton.nodes[w]).norm();
        if (d > threshold[j]) continue;
        distance[w] = d, via[w] = v;
        visited.push_back(w);
      }
    }
    for (int k : visited) {
      if (k == j || !isJunction(k) || distance[k] > threshold[k]) continue;
      merged[j] = merged[k] = 1;
      for (int v = k; v != j; v = via[v]) groups.join(v, j);
    }
    for (int v : visited) distance[v] = -1, via[v] = -1;
  }
  // Each cluster sits at its junctions' centroid, with their largest radius.
  std::vector<Eigen::Vector3d> position = graph.skeleton.nodes, sum(n, Eigen::Vector3d::Zero());
  std::vector<double> radius = graph.skeleton.radii;
  std::vector<int> count(n, 0);
  for (int v = 0; v < n; ++v) {
    const int root = groups.find(v);
    if (merged[v]) sum[root] += graph.skeleton.nodes[v], ++count[root];
    radius[root] = std::max(radius[root], graph.skeleton.radii[v]);
  }
  for (int v = 0; v < n; ++v)
    if (count[v] > 0) position[v] = sum[v] / count[v];
  return contractGroups(graph, groups, std::vector<char>(n, 0), position, radius);
}

int pruneBranches(SketchGraph& graph, const std::vector<double>& threshold) {
  const int n = graph.skeleton.nodeCount();
  const auto neighbours = graph.adjacency();
  std::vector<int> degree(n);
  for (int v = 0; v < n; ++v) degree[v] = int(neighbours[v].size());
  struct Candidate {
    double length;
    std::vector<int> nodes;  // junction first, terminal last
  };
  std::vector<Candidate> candidates;
  for (auto branch : findBranches(n, graph.skeleton.edges)) {
    if (degree[branch.front()] == 1 && degree[branch.back()] >= 3) std::reverse(branch.begin(), branch.end());
    if (degree[branch.front()] < 3 || degree[branch.back()] != 1) continue;
    double length = 0;
    for (size_t k = 1; k < branch.size(); ++k)
      length += (graph.skeleton.nodes[branch[k]] - graph.skeleton.nodes[branch[k - 1]]).norm();
    length += graph.skeleton.radii[branch.back()] -
              graph.skeleton.radii[branch.front()];  // reach beyond the junction's ball
    const double spur = 0.5 * graph.skeleton.radii[branch.front()];
    if (length < std::max(threshold[branch.back()], spur)) candidates.push_back({length, std::move(branch)});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.length < b.length; });
  std::vector<char> deleted(n, 0);
  for (const Candidate& c : candidates) {
    if (degree[c.nodes.front()] <= 1) continue;  // the junction keeps a bone
    --degree[c.nodes.front()];
    for (size_t k = 1; k < c.nodes.size(); ++k) deleted[c.nodes[k]] = 1;
  }
  UnionFind groups{size_t(n)};
  return contractGroups(graph, groups, deleted, graph.skeleton.nodes, graph.skeleton.radii);
}

int collapseEdges(SketchGraph& graph, const std::vector<double>& threshold) {
  const int n = graph.skeleton.nodeCount();
  const auto neighbours = graph.adjacency();
  UnionFind groups{size_t(n)};
  std::vector<Eigen::Vector3d> position = graph.skeleton.nodes;
  std::vector<double> radius = graph.skeleton.radii, limit = threshold;
  std::vector<char> junction(n), internal(n);
  for (int v = 0; v < n; ++v)
    junction[v] = neighbours[v].size() >= 3, internal[v] = neighbours[v].size() >= 2;
  std::vector<int> order(graph.skeleton.edgeCount());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return graph.edgeLength(a) < graph.edgeLength(b); });
  for (int e : order) {
    const int a = groups.find(graph.skeleton.edges[e][0]), b = groups.find(graph.skeleton.edges[e][1]);
    if (a == b || !internal[a] || !internal[b]) continue;
    if ((position[a] - position[b]).norm() >= std::min(limit[a], limit[b])) continue;
    groups.join(b, a);
    position[a] = junction[a] == junction[b] ? Eigen::Vector3d(0.5 * (position[a] + position[b]))
                  : junction[a]              ? position[a]
                                             : position[b];
    radius[a] = std::max(radius[a], radius[b]);
    junction[a] = junction[a] || junction[b];
    limit[a] = std::min(limit[a], limit[b]);
  }
  return contractGroups(graph, groups, std::vector<char>(n, 0), position, radius);
}

}  // namespace medial
