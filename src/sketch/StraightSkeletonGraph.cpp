#include "sketch/StraightSkeletonGraph.h"

#include "common/UnionFind.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/create_straight_skeleton_2.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace medial {
namespace {

using ExactPredicates = CGAL::Exact_predicates_inexact_constructions_kernel;
using DoubleArithmetic = CGAL::Simple_cartesian<double>;

template <class Kernel>
boost::shared_ptr<CGAL::Straight_skeleton_2<Kernel>> buildSkeleton(const Polygon2& polygon) {
  std::vector<typename Kernel::Point_2> points;
  points.reserve(polygon.size());
  for (const auto& p : polygon) points.emplace_back(p.x(), p.y());
  try {
    return CGAL::create_interior_straight_skeleton_2(points.begin(), points.end(), Kernel());
  } catch (const std::exception&) {
    return nullptr;  // CGAL precondition failures on degenerate input
  }
}

template <class Point>
Eigen::Vector2d toEigen(const Point& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
}

// Whether a skeleton built in plain double arithmetic is geometrically sound: CGAL has already checked
// its half-edge structure; here every skeleton vertex must lie inside the polygon, at its offset time from
// the supporting line of each contour edge whose face it bounds (the definition of the straight skeleton),
// and there are n faces and at most n - 2 skeleton vertices for n polygon vertices.
template <class Skeleton>
bool isSound(const Skeleton& skeleton, const Polygon2& polygon) {
  const int n = int(polygon.size());
  if (int(skeleton.size_of_faces()) != n || int(skeleton.size_of_vertices()) > 2 * n - 2) return false;
  Eigen::AlignedBox2d box;
  for (const auto& p : polygon) box.extend(p);
  const double tolerance = 1e-7 * box.diagonal().norm();
  for (auto v = skeleton.vertices_begin(); v != skeleton.vertices_end(); ++v) {
    if (!v->is_skeleton()) continue;
    const Eigen::Vector2d p = toEigen(v->point());
    const double time = CGAL::to_double(v->time());
    if (!p.allFinite() || !(time > 0) || !isInside(polygon, p)) return false;
    auto h = v->halfedge_around_vertex_begin(), end = h;
    do {
      const auto contour = (*h)->defining_contour_edge();
      const Eigen::Vector2d a = toEigen(contour->opposite()->vertex()->point());
      const Eigen::Vector2d b = toEigen(contour->vertex()->point());
      const double length = (b - a).norm();
      if (!(length > 0) || std::abs(std::abs(cross2(b - a, p - a)) / length - time) > tolerance) return false;
    } while (++h != end);
  }
  return true;
}

// The straight skeleton as a graph before collapsing: skeleton vertices and inner bisectors, plus the arms
// of sharp tips (see the header), with each node's offset time.
struct RawSkeleton {
  std::vector<Eigen::Vector2d> nodes;
  std::vector<double> times;  // offset time of each node: its distance to the outline's supporting lines
  std::vector<std::array<int, 2>> edges;
};

template <class Skeleton>
RawSkeleton readSkeleton(const Skeleton& skeleton, const Polygon2& polygon) {
  RawSkeleton raw;
  // Skeleton vertices (not polygon vertices) become nodes; inner bisectors become edges.
  std::map<int, int> nodeOfVertex;
  for (auto v = skeleton.vertices_begin(); v != skeleton.vertices_end(); ++v) {
    if (!v->is_skeleton()) continue;
    nodeOfVertex[v->id()] = int(raw.nodes.size());
    raw.nodes.push_back(toEigen(v->point()));
    raw.times.push_back(CGAL::to_double(v->time()));
  }
  for (auto h = skeleton.halfedges_begin(); h != skeleton.halfedges_end(); ++h) {
    if (!h->is_inner_bisector() || h->id() > h->opposite()->id()) continue;
    raw.edges.push_back({nodeOfVertex.at(h->vertex()->id()), nodeOfVertex.at(h->opposite()->vertex()->id())});
  }
  // A sharp convex vertex (interior angle < 60 degrees) is a tip whose arm is nothing but its peripheral
  // edge, e.g. a star's point. Removing it would cut the arm off, so its inner two thirds stay, ending
  // where the inscribed ball has a third of the node's radius.
  std::map<std::pair<double, double>, int> indexOfPoint;
  for (int i = 0; i < int(polygon.size()); ++i) indexOfPoint[{polygon[i].x(), polygon[i].y()}] = i;
  auto isSharp = [&](const Eigen::Vector2d& p) {
    const auto found = indexOfPoint.find({p.x(), p.y()});
    if (found == indexOfPoint.end()) return false;
    const int i = found->second, n = int(polygon.size());
    const Eigen::Vector2d in = (polygon[i] - polygon[(i + n - 1) % n]).normalized();
    const Eigen::Vector2d out = (polygon[(i + 1) % n] - polygon[i]).normalized();
    const double turn = in.x() * out.y() - in.y() * out.x();  // > 0: convex in a counter-clockwise polygon
    return turn > 0 && (-in).dot(out) > 0.5;                  // the angle between the edges < 60 degrees
  };
  for (auto h = skeleton.halfedges_begin(); h != skeleton.halfedges_end(); ++h) {
    if (!h->is_bisector() || h->is_inner_bisector() || !h->vertex()->is_skeleton()) continue;
    const auto tip = h->opposite()->vertex();
    if (!tip->is_contour()) continue;
    const Eigen::Vector2d tipPoint = toEigen(tip->point());
    if (!isSharp(tipPoint)) continue;
    const int n = nodeOfVertex.at(h->vertex()->id());
    raw.edges.push_back({n, int(raw.nodes.size())});
    raw.nodes.push_back(tipPoint + (raw.nodes[n] - tipPoint) / 3);
    raw.times.push_back(raw.times[n] / 3);
  }
  return raw;
}

// CGAL's skeleton in double arithmetic when it passes isSound (faster: with the filtered kernel
// most of the time goes to exact GMP re-evaluations of event-time comparisons), else with exact predicates.
bool computeSkeleton(const Polygon2& polygon, SkeletonArithmetic arithmetic, RawSkeleton& raw) {
  if (arithmetic == SkeletonArithmetic::automatic) {
    const auto fast = buildSkeleton<DoubleArithmetic>(polygon);
    if (fast && isSound(*fast, polygon)) {
      raw = readSkeleton(*fast, polygon);
      return true;
    }
  }
  const auto exact = buildSkeleton<ExactPredicates>(polygon);
  if (!exact) return false;
  raw = readSkeleton(*exact, polygon);
  return true;
}

}  // namespace

int cgalStraightSkeletonVertexCount(const Polygon2& polygon) {
  const auto skeleton = buildSkeleton<ExactPredicates>(polygon);
  return skeleton ? int(skeleton->size_of_vertices()) : -1;
}

bool straightSkeletonGraph(const Polygon2& polygon, double collapseRatio, SkeletonGraph2& graph,
                           std::string& error, SkeletonArithmetic arithmetic) {
  graph = {};
  RawSkeleton raw;
  if (!computeSkeleton(polygon, arithmetic, raw)) {
    error = "CGAL could not build the straight skeleton of the polygon (degenerate outline)";
    return false;
  }
  graph.nodes = std::move(raw.nodes);
  std::vector<double>& times = raw.times;
  const std::vector<std::array<int, 2>>& edges = raw.edges;
  if (graph.nodes.empty()) {
    error = "the straight skeleton of the polygon has no inner vertex";
    return false;
  }
  // Collapse short edges, shortest first (§3.1: threshold 0.5 x mean skeleton edge length). A merged
  // cluster sits at its most central node (the largest offset time): a part's end node absorbs the short
  // spur into a corner without moving towards it.
  double meanLength = 0;
  for (const auto& e : edges) meanLength += (graph.nodes[e[0]] - graph.nodes[e[1]]).norm();
  meanLength = edges.empty() ? 0 : meanLength / edges.size();
  const double threshold = collapseRatio * meanLength;
  const int n = graph.nodeCount();
  UnionFind clusters{size_t(n)};
  std::vector<int> central(n);  // per cluster root: its most central node
  std::iota(central.begin(), central.end(), 0);
  std::vector<int> order(edges.size());
  std::iota(order.begin(), order.end(), 0);
  auto length = [&](int e) {
    const int a = central[clusters.find(edges[e][0])], b = central[clusters.find(edges[e][1])];
    return (graph.nodes[a] - graph.nodes[b]).norm();
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return length(a) < length(b); });
  for (int e : order) {
    const int a = clusters.find(edges[e][0]), b = clusters.find(edges[e][1]);
    if (a == b || length(e) >= threshold) continue;
    clusters.join(b, a);
    if (times[central[b]] > times[central[a]]) central[a] = central[b];
  }
  std::vector<int> newIndex(n, -1);
  std::vector<Eigen::Vector2d> nodes;
  for (int i = 0; i < n; ++i)
    if (clusters.find(i) == i) newIndex[i] = int(nodes.size()), nodes.push_back(graph.nodes[central[i]]);
  graph.nodes = std::move(nodes);
  std::vector<std::array<int, 2>> kept;
  for (const auto& e : edges) {
    int a = newIndex[clusters.find(e[0])], b = newIndex[clusters.find(e[1])];
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    kept.push_back({a, b});
  }
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  graph.edges = std::move(kept);
  return true;
}

std::vector<std::vector<int>> findBranches(int nodeCount, const std::vector<std::array<int, 2>>& edges) {
  std::vector<std::vector<std::pair<int, int>>> adjacency(nodeCount);  // (neighbour, edge)
  for (int e = 0; e < int(edges.size()); ++e) {
    adjacency[edges[e][0]].push_back({edges[e][1], e});
    adjacency[edges[e][1]].push_back({edges[e][0], e});
  }
  std::vector<char> used(edges.size(), 0);
  std::vector<std::vector<int>> branches;
  auto walk = [&](int start, int neighbour, int edge) {
    std::vector<int> branch{start};
    int previous = start, current = neighbour;
    used[edge] = 1;
    while (true) {
      branch.push_back(current);
      if (adjacency[current].size() != 2 || current == start) break;
      const auto& next = adjacency[current][0].first == previous && !used[adjacency[current][1].second]
                             ? adjacency[current][1]
                         : !used[adjacency[current][0].second] ? adjacency[current][0]
                                                               : adjacency[current][1];
      if (used[next.second]) break;
      used[next.second] = 1;
      previous = current;
      current = next.first;
    }
    branches.push_back(std::move(branch));
  };
  for (int v = 0; v < nodeCount; ++v) {
    if (adjacency[v].size() == 2) continue;
    for (const auto& [neighbour, edge] : adjacency[v])
      if (!used[edge]) walk(v, neighbour, edge);
  }
  for (int v = 0; v < nodeCount; ++v)  // pure cycles of sleeve joints
    for (const auto& [neighbour, edge] : adjacency[v])
      if (!used[edge]) walk(v, neighbour, edge);
  return branches;
}

}  // namespace medial
