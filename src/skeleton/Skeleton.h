/// \file
/// Skeleton: the plain-data model of docs/ARCHITECTURE.md §4, shared by every algorithm of Medial.
///
/// A skeleton is a graph embedded in 3-D: nodes with a sphere radius (and optionally an ellipsoid),
/// undirected edges between node ids, and an optional root. The VTK side (filters/) converts it to and
/// from a vtkPolyData whose points are nodes and whose 2-point lines are edges.
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace medial {

/// A curve skeleton: nodes with optional radii and ellipsoids, edges, and an optional root
/// (docs/ARCHITECTURE.md §4).
struct Skeleton {
  std::vector<Eigen::Vector3d> nodes;     ///< node positions
  std::vector<double> radii;              ///< one per node, > 0; empty means "no radius known"
  std::vector<std::array<int, 2>> edges;  ///< node ids
  std::vector<Eigen::Matrix3d>
      ellipsoidAxes;  ///< optional, one per node: maps the unit sphere to the ellipsoid
  int root = -1;      ///< -1: no root chosen

  /// The number of nodes.
  int nodeCount() const { return static_cast<int>(nodes.size()); }
  /// The number of edges.
  int edgeCount() const { return static_cast<int>(edges.size()); }
};

/// Node types of docs/ARCHITECTURE.md §4 (values of the `NodeType` array).
enum class NodeType : unsigned char { Leaf = 0, Connection = 1, Branch = 2 };

/// One problem found by validateSkeleton, with a message a user can act on.
struct SkeletonProblem {
  /// What kind of problem.
  enum class Kind {
    NonFiniteCoordinate,
    NonPositiveRadius,
    RadiusCountMismatch,
    EllipsoidCountMismatch,
    NonFiniteEllipsoid,
    SelfLoopEdge,
    EdgeIdOutOfRange,
    RootOutOfRange,
  };
  Kind kind;            ///< what kind
  int index;            ///< the node or edge concerned, -1 for the whole skeleton
  std::string message;  ///< what a user reads
};

/// Checks docs/ARCHITECTURE.md §4: finite coordinates, positive finite radii (one per node), no self-loop
/// edges, edge and root ids in range. Returns every problem found (at most maxProblems), empty when the
/// skeleton is valid.
std::vector<SkeletonProblem> validateSkeleton(const Skeleton& skeleton, int maxProblems = 20);

/// Leaf (degree <= 1), connection (degree 2) or branch (degree >= 3) per node. Assumes valid edge ids.
std::vector<NodeType> classifyNodes(const Skeleton& skeleton);

/// Degree of every node. Assumes valid edge ids.
std::vector<int> nodeDegrees(const Skeleton& skeleton);

}  // namespace medial
