#include "contraction/NodeSelection.h"

#include <algorithm>
#include <optional>
#include <queue>
#include <vector>

namespace medial {

namespace {

struct Graph {
  std::vector<Eigen::Vector3d> position;
  std::vector<std::vector<int>> neighbours;
  std::vector<bool> alive;
  std::vector<unsigned> version;
  std::vector<int> owner;

  bool adjacent(int a, int b) const {
    return std::find(neighbours[a].begin(), neighbours[a].end(), b) != neighbours[a].end();
  }
  bool shareNeighbour(int a, int b) const {
    for (int k : neighbours[a])
      if (k != b && adjacent(b, k)) return true;
    return false;
  }
  // 2: leaf, 1: branch node, 0: connection node.
  int significance(int a) const {
    const size_t degree = neighbours[a].size();
    return degree <= 1 ? 2 : degree >= 3 ? 1 : 0;
  }
  double length(int a, int b) const { return (position[a] - position[b]).norm(); }
};

struct Placement {
  int keep;
  Eigen::Vector3d position;
};

struct Candidate {
  double length;
  int a, b;
  unsigned versionA, versionB;
  bool operator>(const Candidate& other) const { return length > other.length; }
};

// Would the merged node at `kept` have no more edges leaving the mesh than its two ends had? (Edges of
// the surgery that already cross the surface do not block a collapse; new crossings do.)
bool staysInside(const Graph& g, const InsideTest& inside, const Eigen::Vector3d& kept, int keep, int drop) {
  int crossingBefore = 0, crossingAfter = 0;
  for (int node : {keep, drop})
    for (int k : g.neighbours[size_t(node)]) {
      if (k == keep || k == drop) continue;
      crossingBefore += !inside.segmentIsClear(g.position[size_t(node)], g.position[size_t(k)]);
      crossingAfter += !inside.segmentIsClear(kept, g.position[size_t(k)]);
    }
  return crossingAfter <= crossingBefore;
}

// Where the merged node of a candidate edge goes: the preferred placement, and in the second pass either
// end when that one would take an edge out of the mesh.
std::optional<Placement> placementOf(const Graph& g, const InsideTest* inside, const Candidate& c,
                                     bool eitherEnd) {
  const int sa = g.significance(c.a), sb = g.significance(c.b);
  // Keep the more significant end: a tip or a junction stays where it is. A leaf on a branch node is
  // the one case where the branch node is kept: the side branch, the shortest edge left, goes.
  int keep = sa >= sb ? c.a : c.b;
  if (sa == 2 && sb == 1) keep = c.b;
  if (sb == 2 && sa == 1) keep = c.a;
  const Eigen::Vector3d preferred =
      sa == sb ? Eigen::Vector3d(0.5 * (g.position[size_t(c.a)] + g.position[size_t(c.b)]))
               : g.position[size_t(keep)];
  std::vector<Placement> placements{{keep, preferred}};
  if (eitherEnd)
    for (int end : {c.a, c.b})
      if (g.position[size_t(end)] != preferred) placements.push_back({end, g.position[size_t(end)]});
  for (const Placement& placement : placements)
    if (!inside ||
        staysInside(g, *inside, placement.position, placement.keep, placement.keep == c.a ? c.b : c.a))
      return placement;
  return std::nullopt;
}

void collapse(Graph& g, const Placement& placement, int drop) {
  const int keep = placement.keep;
  g.position[size_t(keep)] = placement.position;
  for (int k : g.neighbours[size_t(drop)]) {
    auto& list = g.neighbours[size_t(k)];
    list.erase(std::remove(list.begin(), list.end(), drop), list.end());
    if (k != keep && !g.adjacent(keep, k)) {
      g.neighbours[size_t(keep)].push_back(k);
      list.push_back(keep);
    }
    ++g.version[size_t(k)];
  }
  g.neighbours[size_t(drop)].clear();
  g.alive[size_t(drop)] = false;
  g.owner[size_t(drop)] = keep;
  ++g.version[size_t(keep)];
}

// Collapses the shortest collapsible edges until `aliveCount` reaches the target or none is left; returns
// the collapses.
int collapseShortestEdges(Graph& g, const InsideTest* inside, int targetNodes, bool eitherEnd,
                          int& aliveCount) {
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue;
  auto push = [&](int a, int b) {
    queue.push({g.length(a, b), a, b, g.version[size_t(a)], g.version[size_t(b)]});
  };
  for (int a = 0; a < int(g.position.size()); ++a)
    if (g.alive[size_t(a)])
      for (int b : g.neighbours[size_t(a)])
        if (a < b) push(a, b);
  int collapses = 0;
  while (aliveCount > targetNodes && !queue.empty()) {
    const Candidate c = queue.top();
    queue.pop();
    if (!g.alive[size_t(c.a)] || !g.alive[size_t(c.b)] || g.version[size_t(c.a)] != c.versionA ||
        g.version[size_t(c.b)] != c.versionB || !g.adjacent(c.a, c.b))
      continue;
    if (g.significance(c.a) == 2 && g.significance(c.b) == 2) continue;  // a segment on its own
    if (g.shareNeighbour(c.a, c.b)) continue;  // would fold a cycle into a double edge
    const std::optional<Placement> placement = placementOf(g, inside, c, eitherEnd);
    if (!placement) continue;
    const int keep = placement->keep;
    collapse(g, *placement, keep == c.a ? c.b : c.a);
    --aliveCount;
    ++collapses;
    // Lengths around the kept node changed; the significance of its neighbours may have changed too.
    for (int k : g.neighbours[size_t(keep)]) {
      push(keep, k);
      for (int m : g.neighbours[size_t(k)])
        if (m != keep) push(k, m);
    }
  }
  return collapses;
}

}  // namespace

int selectNodes(CurveSkeleton& skeleton, int targetNodes, const InsideTest* inside,
                std::vector<int>* cameFrom) {
  const int n = int(skeleton.nodes.rows());
  Graph g{std::vector<Eigen::Vector3d>(size_t(n)), std::vector<std::vector<int>>(size_t(n)),
          std::vector<bool>(size_t(n), true), std::vector<unsigned>(size_t(n), 0),
          std::vector<int>(size_t(n))};
  for (int i = 0; i < n; ++i) {
    g.position[size_t(i)] = skeleton.nodes.row(i).transpose();
    g.owner[size_t(i)] = i;
  }
  for (const auto& [a, b] : skeleton.edges)
    if (a != b && !g.adjacent(a, b)) {
      g.neighbours[size_t(a)].push_back(b);
      g.neighbours[size_t(b)].push_back(a);
    }

  int aliveCount = n;
  int collapses = collapseShortestEdges(g, inside, targetNodes, /*eitherEnd=*/false, aliveCount);
  // Stopped above the target because every merge at the preferred place would take an edge out of the
  // mesh (a curled finger's tip joined to the palm): again, with the merged node at either end - the count
  // asked for matters more to a rigger than a tip a node short.
  if (inside && aliveCount > targetNodes)
    collapses += collapseShortestEdges(g, inside, targetNodes, /*eitherEnd=*/true, aliveCount);

  // Renumber the surviving nodes and map every absorbed vertex through the merge chain.
  std::vector<int> newId(size_t(n), -1);
  std::vector<Eigen::Vector3d> nodes;
  if (cameFrom) cameFrom->clear();
  for (int i = 0; i < n; ++i)
    if (g.alive[size_t(i)]) {
      newId[size_t(i)] = int(nodes.size());
      nodes.push_back(g.position[size_t(i)]);
      if (cameFrom) cameFrom->push_back(i);
    }
  auto finalOwner = [&](int i) {
    while (g.owner[size_t(i)] != i) i = g.owner[size_t(i)];
    return i;
  };
  skeleton.nodes.resize(Eigen::Index(nodes.size()), 3);
  for (size_t k = 0; k < nodes.size(); ++k) skeleton.nodes.row(Eigen::Index(k)) = nodes[k].transpose();
  skeleton.edges.clear();
  for (int a = 0; a < n; ++a)
    if (g.alive[size_t(a)])
      for (int b : g.neighbours[size_t(a)])
        if (a < b) skeleton.edges.emplace_back(newId[size_t(a)], newId[size_t(b)]);
  for (int& node : skeleton.vertexToNode)
    if (node >= 0) node = newId[size_t(finalOwner(node))];
  return collapses;
}

}  // namespace medial
