#include "skeleton/Skeleton.h"

#include <cmath>
#include <sstream>

namespace medial {
namespace {

std::string describePoint(const Eigen::Vector3d& p) {
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

class ProblemList {
 public:
  explicit ProblemList(int limit) : limit_(limit) {}
  bool full() const { return static_cast<int>(problems_.size()) >= limit_; }
  void add(SkeletonProblem::Kind kind, int index, std::string message) {
    if (!full()) problems_.push_back({kind, index, std::move(message)});
  }
  std::vector<SkeletonProblem> take() { return std::move(problems_); }

 private:
  int limit_;
  std::vector<SkeletonProblem> problems_;
};

}  // namespace

std::vector<SkeletonProblem> validateSkeleton(const Skeleton& skeleton, int maxProblems) {
  using Kind = SkeletonProblem::Kind;
  ProblemList problems(maxProblems);
  const int n = skeleton.nodeCount();

  for (int i = 0; i < n && !problems.full(); ++i) {
    if (!skeleton.nodes[i].allFinite())
      problems.add(
          Kind::NonFiniteCoordinate, i,
          "node " + std::to_string(i) + " has non-finite coordinates " + describePoint(skeleton.nodes[i]));
  }

  if (!skeleton.radii.empty()) {
    if (static_cast<int>(skeleton.radii.size()) != n) {
      problems.add(Kind::RadiusCountMismatch, -1,
                   std::to_string(skeleton.radii.size()) + " radii for " + std::to_string(n) + " nodes");
    } else {
      for (int i = 0; i < n && !problems.full(); ++i) {
        const double r = skeleton.radii[i];
        if (!(std::isfinite(r) && r > 0.0)) {
          std::ostringstream msg;
          msg << "node " << i << " has radius " << r << " (radii must be positive and finite)";
          problems.add(Kind::NonPositiveRadius, i, msg.str());
        }
      }
    }
  }

  if (!skeleton.ellipsoidAxes.empty()) {
    if (static_cast<int>(skeleton.ellipsoidAxes.size()) != n) {
      problems.add(Kind::EllipsoidCountMismatch, -1,
                   std::to_string(skeleton.ellipsoidAxes.size()) + " ellipsoid matrices for " +
                       std::to_string(n) + " nodes");
    } else {
      for (int i = 0; i < n && !problems.full(); ++i)
        if (!skeleton.ellipsoidAxes[i].allFinite())
          problems.add(Kind::NonFiniteEllipsoid, i,
                       "node " + std::to_string(i) + " has a non-finite ellipsoid matrix");
    }
  }

  for (int e = 0; e < skeleton.edgeCount() && !problems.full(); ++e) {
    const auto [a, b] = skeleton.edges[e];
    if (a < 0 || a >= n || b < 0 || b >= n) {
      problems.add(Kind::EdgeIdOutOfRange, e,
                   "edge " + std::to_string(e) + " joins nodes " + std::to_string(a) + " and " +
                       std::to_string(b) + " but node ids run from 0 to " + std::to_string(n - 1));
    } else if (a == b) {
      problems.add(Kind::SelfLoopEdge, e,
                   "edge " + std::to_string(e) + " is a self-loop on node " + std::to_string(a));
    }
  }

  if (skeleton.root != -1 && (skeleton.root < 0 || skeleton.root >= n))
    problems.add(
        Kind::RootOutOfRange, -1,
        "root " + std::to_string(skeleton.root) + " is not a node id (0.." + std::to_string(n - 1) + ")");

  return problems.take();
}

std::vector<int> nodeDegrees(const Skeleton& skeleton) {
  std::vector<int> degree(skeleton.nodes.size(), 0);
  for (const auto& [a, b] : skeleton.edges) {
    ++degree[a];
    ++degree[b];
  }
  return degree;
}

std::vector<NodeType> classifyNodes(const Skeleton& skeleton) {
  const std::vector<int> degree = nodeDegrees(skeleton);
  std::vector<NodeType> types(degree.size());
  for (size_t i = 0; i < degree.size(); ++i)
    types[i] = degree[i] <= 1 ? NodeType::Leaf : degree[i] == 2 ? NodeType::Connection : NodeType::Branch;
  return types;
}

}  // namespace medial
