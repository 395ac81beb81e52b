#include "contraction/NodeRadii.h"

#include <algorithm>
#include <cmath>

namespace medial {

std::vector<double> nodeRadii(const CurveSkeleton& skeleton, const Vertices& originalVertices,
                              const InsideTest& surface) {
  const size_t nodeCount = size_t(skeleton.nodes.rows());
  std::vector<std::vector<double>> distances(nodeCount);
  for (size_t v = 0; v < skeleton.vertexToNode.size(); ++v) {
    const int node = skeleton.vertexToNode[v];
    if (node >= 0)
      distances[size_t(node)].push_back(
          (originalVertices.row(Eigen::Index(v)) - skeleton.nodes.row(node)).norm());
  }
  // A floor keeps radii positive (docs/ARCHITECTURE.md §4) for a node that sits on the surface.
  const double floor =
      1e-6 * (originalVertices.colwise().maxCoeff() - originalVertices.colwise().minCoeff()).norm();
  std::vector<double> radii(nodeCount);
  for (size_t k = 0; k < nodeCount; ++k) {
    auto& d = distances[k];
    double radius = 0;
    if (d.size() >= 3) {
      std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
      radius = d[d.size() / 2];
    } else {  // too few absorbed vertices for a median: the distance to the surface
      radius = std::sqrt(surface.squaredDistanceToSurface(skeleton.nodes.row(Eigen::Index(k)).transpose()));
    }
    radii[k] = std::max(radius, floor);
  }
  return radii;
}

}  // namespace medial
