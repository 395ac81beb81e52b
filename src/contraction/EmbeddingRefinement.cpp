#include "contraction/EmbeddingRefinement.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace medial {

namespace {

// Where the centroid of the absorbed vertices is no good (a one-sided patch: its centroid lies on or
// outside the surface), the split node is sought in the disc through the edge's midpoint, perpendicular to
// it: 6 rings of 12 points out to the larger of half the edge and the ends' distances to the surface.
// Among the inside points, those from which both halves of the edge stay inside win; then the one
// farthest from the surface (the most central). Returns false when no point of the disc is inside.
bool insidePointNearMiddle(const Eigen::Vector3d& pa, const Eigen::Vector3d& pb, const InsideTest& inside,
                           Eigen::Vector3d& best) {
  const Eigen::Vector3d middle = 0.5 * (pa + pb), axis = (pb - pa).normalized();
  const Eigen::Vector3d u = axis.unitOrthogonal(), w = axis.cross(u);
  const double reach = std::max({0.5 * (pb - pa).norm(), std::sqrt(inside.squaredDistanceToSurface(pa)),
                                 std::sqrt(inside.squaredDistanceToSurface(pb))});
  constexpr int rings = 6, spokes = 12;
  std::pair<int, double> bestScore{-1, 0.0};
  for (int ring = 0; ring <= rings; ++ring)
    for (int spoke = 0; spoke < (ring == 0 ? 1 : spokes); ++spoke) {
      const double angle = 2 * M_PI * spoke / spokes, radius = reach * ring / rings;
      const Eigen::Vector3d p = middle + radius * (std::cos(angle) * u + std::sin(angle) * w);
      if (!inside.contains(p)) continue;
      const std::pair<int, double> score{int(inside.segmentIsClear(pa, p) && inside.segmentIsClear(p, pb)),
                                         inside.squaredDistanceToSurface(p)};
      if (score > bestScore) {
        bestScore = score;
        best = p;
      }
    }
  return bestScore.first >= 0;
}

}  // namespace

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

int pushNodesInside(CurveSkeleton& skeleton, const InsideTest& inside) {
  if (skeleton.nodes.rows() == 0) return 0;
  const double diagonal = (skeleton.nodes.colwise().maxCoeff() - skeleton.nodes.colwise().minCoeff()).norm();
  int moved = 0;
  for (Eigen::Index k = 0; k < skeleton.nodes.rows(); ++k) {
    const Eigen::Vector3d p = skeleton.nodes.row(k).transpose();
    if (inside.contains(p)) continue;
    const Eigen::Vector3d surface = inside.closestSurfacePoint(p);
    const double outside = (surface - p).norm();
    if (outside == 0) continue;
    const Eigen::Vector3d inward = (surface - p) / outside;
    // Steps of a quarter of the node's distance outside, at least 1/1000 of the skeleton's extent.
    const double step = std::max(0.25 * outside, 1e-3 * diagonal);
    Eigen::Vector3d best = p;
    double bestDistance = -1;
    for (int i = 1; i <= 400; ++i) {
      const Eigen::Vector3d q = surface + (i - 0.5) * step * inward;
      if (!inside.contains(q)) {
        if (bestDistance >= 0) break;  // through the part and out again
        continue;
      }
      const double distance = inside.squaredDistanceToSurface(q);
      if (distance < bestDistance) break;
      bestDistance = distance;
      best = q;
    }
    if (bestDistance < 0) continue;
    skeleton.nodes.row(k) = best.transpose();
    ++moved;
  }
  return moved;
}

int splitSkeletonEdges(CurveSkeleton& skeleton, const Vertices& originalVertices, int maxDepth,
                       const SplitPoint& splitPoint) {
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
    return k < skeleton.nodes.rows() ? Eigen::Vector3d(skeleton.nodes.row(k).transpose())
                                     : added[size_t(k - skeleton.nodes.rows())];
  };
  while (!pending.empty()) {
    const Pending e = pending.back();
    pending.pop_back();
    const Eigen::Vector3d pa = position(e.a), pb = position(e.b), ab = pb - pa;
    if (e.depth >= maxDepth || ab.squaredNorm() == 0) {
      edges.emplace_back(e.a, e.b);
      continue;
    }
    std::vector<int> middle;  // absorbed vertices of both ends over the middle half of the edge
    for (int end : {e.a, e.b})
      for (int v : absorbed[size_t(end)]) {
        const double t = (originalVertices.row(v).transpose() - pa).dot(ab) / ab.squaredNorm();
        if (t >= 0.25 && t <= 0.75) middle.push_back(v);
      }
    Eigen::Vector3d point;
    if (!splitPoint(pa, pb, middle, point)) {
      edges.emplace_back(e.a, e.b);
      continue;
    }
    const int k = int(skeleton.nodes.rows() + Eigen::Index(added.size()));
    added.push_back(point);
    for (int end : {e.a, e.b}) {
      auto& list = absorbed[size_t(end)];
      list.erase(
          std::remove_if(list.begin(), list.end(),
                         [&](int v) { return std::find(middle.begin(), middle.end(), v) != middle.end(); }),
          list.end());
    }
    absorbed.emplace_back(std::move(middle));
    pending.push_back({e.a, k, e.depth + 1});
    pending.push_back({k, e.b, e.depth + 1});
  }
  if (added.empty()) return 0;
  const Eigen::Index first = skeleton.nodes.rows();
  skeleton.nodes.conservativeResize(first + Eigen::Index(added.size()), 3);
  for (size_t k = 0; k < added.size(); ++k)
    skeleton.nodes.row(first + Eigen::Index(k)) = added[k].transpose();
  skeleton.edges = std::move(edges);
  for (size_t node = 0; node < absorbed.size(); ++node)
    for (int v : absorbed[node]) skeleton.vertexToNode[size_t(v)] = int(node);
  return int(added.size());
}

int splitEdgesLeavingTheMesh(CurveSkeleton& skeleton, const Vertices& originalVertices,
                             const InsideTest& inside, int maxDepth) {
  const SplitPoint whereItLeaves = [&](const Eigen::Vector3d& pa, const Eigen::Vector3d& pb,
                                       const std::vector<int>& middle, Eigen::Vector3d& point) {
    if (inside.segmentIsClear(pa, pb)) return false;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int v : middle) sum += originalVertices.row(v).transpose();
    point = middle.empty() ? pa : Eigen::Vector3d(sum / double(middle.size()));
    return (middle.size() >= 3 && inside.contains(point)) || insidePointNearMiddle(pa, pb, inside, point);
  };
  return splitSkeletonEdges(skeleton, originalVertices, maxDepth, whereItLeaves);
}

}  // namespace medial
