#include "sketch/SketchGraph.h"

#include <algorithm>
#include <set>

namespace medial {

int SketchGraph::addNode(const Eigen::Vector3d& position, double radius, int part) {
  skeleton.nodes.push_back(position);
  skeleton.radii.push_back(radius);
  nodePart.push_back(part);
  return skeleton.nodeCount() - 1;
}

void SketchGraph::addEdge(int a, int b, int part, int branch) {
  skeleton.edges.push_back({a, b});
  edgePart.push_back(part);
  edgeBranch.push_back(branch);
}

std::vector<std::vector<int>> SketchGraph::adjacency() const {
  std::vector<std::vector<int>> neighbours(skeleton.nodeCount());
  for (const auto& e : skeleton.edges) {
    neighbours[e[0]].push_back(e[1]);
    neighbours[e[1]].push_back(e[0]);
  }
  return neighbours;
}

double SketchGraph::edgeLength(int edge) const {
  const auto& e = skeleton.edges[edge];
  return (skeleton.nodes[e[0]] - skeleton.nodes[e[1]]).norm();
}

void SketchGraph::contract(const std::vector<int>& target, const std::vector<Eigen::Vector3d>& positions,
                           const std::vector<double>& radii, const std::vector<int>& parts) {
  SketchGraph result;
  result.skeleton.nodes = positions;
  result.skeleton.radii = radii;
  result.nodePart = parts;
  std::set<std::pair<int, int>> seen;
  for (int e = 0; e < skeleton.edgeCount(); ++e) {
    const int a = target[skeleton.edges[e][0]], b = target[skeleton.edges[e][1]];
    if (a < 0 || b < 0 || a == b || !seen.insert({std::min(a, b), std::max(a, b)}).second) continue;
    result.addEdge(a, b, edgePart[e], edgeBranch[e]);
  }
  result.skeleton.root = skeleton.root >= 0 ? target[skeleton.root] : -1;
  *this = std::move(result);
}

}  // namespace medial
