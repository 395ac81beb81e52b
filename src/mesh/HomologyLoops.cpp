#include "mesh/HomologyLoops.h"

#include "common/UnionFind.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <queue>
#include <unordered_map>

namespace medial {

namespace {

struct Edge {
  int a, b;
  std::vector<int> faces;
};

struct EdgeGraph {
  std::vector<Edge> edges;
  std::vector<std::vector<std::pair<int, int>>> around;  // per vertex: (neighbour, edge id)
};

EdgeGraph buildEdges(const TriangleMesh& mesh) {
  EdgeGraph g;
  g.around.resize(size_t(mesh.vertices.rows()));
  std::unordered_map<uint64_t, int> id;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int a = std::min(mesh.faces(f, c), mesh.faces(f, (c + 1) % 3));
      const int b = std::max(mesh.faces(f, c), mesh.faces(f, (c + 1) % 3));
      const uint64_t key = (uint64_t(uint32_t(a)) << 32) | uint32_t(b);
      auto [it, added] = id.emplace(key, int(g.edges.size()));
      if (added) {
        g.edges.push_back({a, b, {}});
        g.around[size_t(a)].emplace_back(b, it->second);
        g.around[size_t(b)].emplace_back(a, it->second);
      }
      g.edges[size_t(it->second)].faces.push_back(int(f));
    }
  return g;
}

}  // namespace

std::vector<int> loopThroughTree(int a, int b, const std::vector<int>& parent,
                                 const std::vector<int>& depth) {
  std::vector<int> fromA{a}, fromB{b};
  while (fromA.back() != fromB.back()) {
    std::vector<int>& deeper = depth[size_t(fromA.back())] >= depth[size_t(fromB.back())] ? fromA : fromB;
    deeper.push_back(parent[size_t(deeper.back())]);
  }
  std::vector<int> loop(fromA.rbegin(), fromA.rend());
  loop.insert(loop.end(), fromB.begin(), fromB.end() - 1);
  return loop;
}

int closedGenus(const TriangleMesh& mesh) {
  // Edges as sorted vertex pairs: each must appear exactly twice in a closed 2-manifold.
  std::vector<std::pair<int, int>> halfEdges;
  halfEdges.reserve(size_t(3 * mesh.faces.rows()));
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    for (int c = 0; c < 3; ++c)
      halfEdges.push_back(std::minmax(mesh.faces(f, c), mesh.faces(f, (c + 1) % 3)));
  std::sort(halfEdges.begin(), halfEdges.end());
  UnionFind component{size_t(mesh.vertices.rows())};
  for (const auto& [a, b] : halfEdges) component.join(a, b);
  const size_t n = size_t(mesh.vertices.rows());
  std::vector<bool> closed(n, true);
  std::vector<long> euler(n, 0);  // V - E + F per component root
  for (size_t i = 0; i < halfEdges.size();) {
    size_t j = i;
    while (j < halfEdges.size() && halfEdges[j] == halfEdges[i]) ++j;
    const int root = component.find(halfEdges[i].first);
    if (j - i != 2) closed[size_t(root)] = false;
    --euler[size_t(root)];
    i = j;
  }
  std::vector<bool> used(n, false);
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    ++euler[size_t(component.find(mesh.faces(f, 0)))];
    for (int c = 0; c < 3; ++c) used[size_t(mesh.faces(f, c))] = true;
  }
  for (size_t v = 0; v < n; ++v)
    if (used[v]) ++euler[size_t(component.find(int(v)))];
  long genus = 0;
  for (size_t v = 0; v < n; ++v)
    if (used[v] && component.find(int(v)) == int(v) && closed[v]) genus += (2 - euler[v]) / 2;
  return int(genus);
}

std::vector<std::vector<int>> homologyBasisLoops(const TriangleMesh& mesh) {
  const EdgeGraph g = buildEdges(mesh);
  const size_t vertexCount = size_t(mesh.vertices.rows());
  // Components of the vertices faces use; a component with a border or non-manifold edge is left out.
  UnionFind component(vertexCount);
  for (const Edge& e : g.edges) component.join(e.a, e.b);
  std::vector<bool> closed(vertexCount, true);
  for (const Edge& e : g.edges)
    if (e.faces.size() != 2) closed[size_t(component.find(e.a))] = false;

  // Shortest-path forest, one tree per closed component, from its first vertex.
  std::vector<double> distance(vertexCount, INFINITY);
  std::vector<int> parent(vertexCount, -1), parentEdge(vertexCount, -1), depth(vertexCount, 0);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  std::vector<bool> rooted(vertexCount, false);
  for (const Edge& e : g.edges) {
    const int root = component.find(e.a);
    if (!closed[size_t(root)] || rooted[size_t(root)]) continue;
    rooted[size_t(root)] = true;
    distance[size_t(e.a)] = 0;
    queue.push({0.0, e.a});
  }
  auto length = [&](const Edge& e) { return (mesh.vertices.row(e.a) - mesh.vertices.row(e.b)).norm(); };
  while (!queue.empty()) {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > distance[size_t(u)]) continue;
    for (const auto& [v, edge] : g.around[size_t(u)]) {
      const double candidate = d + length(g.edges[size_t(edge)]);
      if (candidate < distance[size_t(v)]) {
        distance[size_t(v)] = candidate;
        parent[size_t(v)] = u;
        parentEdge[size_t(v)] = edge;
        depth[size_t(v)] = depth[size_t(u)] + 1;
        queue.push({candidate, v});
      }
    }
  }
  std::vector<bool> inTree(g.edges.size(), false);
  for (size_t v = 0; v < vertexCount; ++v)
    if (parentEdge[v] >= 0) inTree[size_t(parentEdge[v])] = true;

  // The dual's maximum spanning tree over the other edges, longest loops first; what is left are the
  // generators (Erickson & Whittlesey: the shortest basis of loops through the base vertex).
  std::vector<int> others;
  for (size_t e = 0; e < g.edges.size(); ++e)
    if (!inTree[e] && closed[size_t(component.find(g.edges[e].a))]) others.push_back(int(e));
  auto loopLength = [&](int e) {
    const Edge& edge = g.edges[size_t(e)];
    return distance[size_t(edge.a)] + distance[size_t(edge.b)] + length(edge);
  };
  std::sort(others.begin(), others.end(), [&](int x, int y) { return loopLength(x) > loopLength(y); });
  UnionFind dual{size_t(mesh.faces.rows())};
  std::vector<std::vector<int>> loops;
  for (int e : others) {
    const Edge& edge = g.edges[size_t(e)];
    if (dual.join(edge.faces[0], edge.faces[1])) continue;
    loops.push_back(loopThroughTree(edge.a, edge.b, parent, depth));
  }
  return loops;
}

}  // namespace medial
