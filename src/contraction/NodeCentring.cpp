#include "contraction/NodeCentring.h"

#include "contraction/EmbeddingRefinement.h"

#include <cmath>
#include <vector>

namespace medial {

namespace {
// The skeleton's direction at a node: from the node kHops edges back to the one kHops edges on (fewer at
// a branch or a leaf). One short edge's direction is noisy and tilts the cut; on the sample meshes 5 hops
// and two passes gave the lowest off-centre medians of the settings tried (1-5 hops, 2-4 passes).
constexpr int kHops = 5;
// splitOffCentreEdges: the largest bend a new node may make (30 degrees gained less, no limit zigzagged).
const double kMaxSplitBend = M_PI / 4;

std::vector<std::vector<int>> nodeNeighbours(const CurveSkeleton& skeleton) {
  std::vector<std::vector<int>> neighbours(static_cast<size_t>(skeleton.nodes.rows()));
  for (const auto& [a, b] : skeleton.edges) {
    neighbours[size_t(a)].push_back(b);
    neighbours[size_t(b)].push_back(a);
  }
  return neighbours;
}

// The skeleton's direction at `node`, over kHops edges each way; zero at a node without edges.
Eigen::Vector3d skeletonDirection(const Vertices& nodes, const std::vector<std::vector<int>>& neighbours,
                                  int node) {
  auto position = [&](int k) -> Eigen::Vector3d { return nodes.row(k).transpose(); };
  const std::vector<int>& around = neighbours[size_t(node)];
  const Eigen::Vector3d here = position(node);
  // The direction over a few edges each way: one short edge's direction is noisy. ends[i]: the node
  // reached from this one through its i-th edge.
  std::vector<Eigen::Vector3d> ends;
  for (int first : around) {
    int from = node, next = first;
    for (int hop = 1; hop < kHops; ++hop) {
      const auto& onward = neighbours[size_t(next)];
      if (onward.size() != 2) break;
      const int after = onward[0] == from ? onward[1] : onward[0];
      from = next;
      next = after;
    }
    ends.push_back(position(next));
  }
  if (ends.empty()) return Eigen::Vector3d::Zero();
  if (around.size() == 1) return here - ends[0];
  // Through the node along its straightest pair of edges (at a node of two edges, the only pair).
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  double leastBend = INFINITY;
  for (size_t i = 0; i < ends.size(); ++i)
    for (size_t j = i + 1; j < ends.size(); ++j) {
      const double bend = 1 - (here - ends[i]).normalized().dot((ends[j] - here).normalized());
      if (bend < leastBend) {
        leastBend = bend;
        direction = ends[j] - ends[i];
      }
    }
  return direction;
}

}  // namespace

int centreNodes(CurveSkeleton& skeleton, const CrossSections& sections, const InsideTest& inside,
                bool branchNodes, int passes, const std::vector<Eigen::Vector3d>* directions) {
  const Eigen::Index n = skeleton.nodes.rows();
  const std::vector<std::vector<int>> neighbours = nodeNeighbours(skeleton);
  auto position = [&](int k) -> Eigen::Vector3d { return skeleton.nodes.row(k).transpose(); };
  int moves = 0;
  for (int pass = 0; pass < passes; ++pass) {
    // Every node's target first (its section's centroid, or where it is), all against the same skeleton,
    // so that the targets do not depend on the order of the nodes; then the moves whose edges stay inside.
    Vertices target = skeleton.nodes;
    std::vector<bool> moving(static_cast<size_t>(n), false);
    for (Eigen::Index k = 0; k < n; ++k) {
      const std::vector<int>& around = neighbours[size_t(k)];
      if (around.empty() || (around.size() > 2 && !branchNodes)) continue;
      const Eigen::Vector3d here = position(int(k));
      const Eigen::Vector3d direction = directions && !(*directions)[size_t(k)].isZero()
                                            ? (*directions)[size_t(k)]
                                            : skeletonDirection(skeleton.nodes, neighbours, int(k));
      const CrossSection section = sections.around(here, direction);
      if (!section.found || section.offCentre(here) > 1 || !inside.contains(section.centroid)) continue;
      target.row(k) = section.centroid.transpose();
      moving[size_t(k)] = true;
    }
    // A move is kept when every edge of the node, to its neighbour's target, stays inside the mesh. A
    // rejected node stays where it is, so its moving neighbours are checked again against that (in sweeps
    // over the nodes in order, each testing only the nodes whose neighbourhood changed: one to three sweeps
    // on the samples).
    std::vector<bool> check = moving;
    bool again = true;
    while (again) {
      again = false;
      for (Eigen::Index k = 0; k < n; ++k) {
        if (!check[size_t(k)]) continue;
        check[size_t(k)] = false;
        const Eigen::Vector3d to = target.row(k).transpose();
        bool keep = true;
        for (int m : neighbours[size_t(k)])
          keep = keep && inside.segmentIsClear(to, target.row(m).transpose());
        if (keep) continue;
        moving[size_t(k)] = false;
        target.row(k) = skeleton.nodes.row(k);
        for (int m : neighbours[size_t(k)])
          if (moving[size_t(m)]) again = check[size_t(m)] = true;
      }
    }
    for (Eigen::Index k = 0; k < n; ++k) moves += moving[size_t(k)] ? 1 : 0;
    skeleton.nodes = target;
  }
  return moves;
}

std::vector<Eigen::Vector3d> nodeDirections(const CurveSkeleton& skeleton) {
  const std::vector<std::vector<int>> neighbours = nodeNeighbours(skeleton);
  std::vector<Eigen::Vector3d> directions(neighbours.size());
  for (size_t k = 0; k < neighbours.size(); ++k)
    directions[k] = skeletonDirection(skeleton.nodes, neighbours, int(k));
  return directions;
}

std::vector<double> nodeOffCentre(const Vertices& nodes, const std::vector<Eigen::Vector3d>& directions,
                                  const CrossSections& sections) {
  std::vector<double> ratios(directions.size(), NAN);
  for (size_t k = 0; k < directions.size(); ++k) {
    if (directions[k].isZero()) continue;
    const Eigen::Vector3d here = nodes.row(Eigen::Index(k)).transpose();
    const CrossSection section = sections.around(here, directions[k]);
    if (section.found) ratios[k] = section.offCentre(here);
  }
  return ratios;
}

int splitOffCentreEdges(CurveSkeleton& skeleton, const Vertices& originalVertices,
                        const CrossSections& sections, const InsideTest& inside, double threshold,
                        int maxDepth) {
  const SplitPoint atTheCentroid = [&](const Eigen::Vector3d& pa, const Eigen::Vector3d& pb,
                                       const std::vector<int>&, Eigen::Vector3d& point) {
    const Eigen::Vector3d middle = 0.5 * (pa + pb);
    const CrossSection section = sections.around(middle, pb - pa);
    if (!section.found) return false;
    const double ratio = section.offCentre(middle);
    if (ratio <= threshold || ratio > 1) return false;
    point = section.centroid;
    const Eigen::Vector3d in = point - pa, out = pb - point;
    const bool smooth =
        in.norm() > 0 && out.norm() > 0 && in.normalized().dot(out.normalized()) >= std::cos(kMaxSplitBend);
    return smooth && inside.contains(point) && inside.segmentIsClear(pa, point) &&
           inside.segmentIsClear(point, pb);
  };
  return splitSkeletonEdges(skeleton, originalVertices, maxDepth, atTheCentroid);
}

}  // namespace medial
