/// \file
/// SkeletonEdits: the edits of the skeleton editor (SQM paper §6: an interactive editor whose mesh follows
/// every change), on the plain skeleton, so that the GUI, Python and tests share them. Each keeps the
/// skeleton valid (radii, ellipsoid axes and root follow the nodes) and returns false, changing nothing,
/// when its ids are out of range.
#pragma once

#include "skeleton/Skeleton.h"

namespace medial {

/// Moves the node to `position`; false when the node does not exist.
bool moveNode(Skeleton& skeleton, int node, const Eigen::Vector3d& position);

/// A skeleton without radii gets 1 % of its bounding-box diagonal at every node (what an editor shows and
/// SQM meshes until the user sets them).
void ensureRadii(Skeleton& skeleton);

/// Sets the node's radius (> 0); a skeleton without radii gets them, every other node 1 % of its extent.
bool setNodeRadius(Skeleton& skeleton, int node, double radius);

/// A new node on `edge` at parameter t in (0, 1) from its first node, with the radius interpolated there;
/// the edge becomes two. Returns the new node, -1 when the edge does not exist.
int splitEdge(Skeleton& skeleton, int edge, double t);

/// A new leaf node at `position` joined to `node` (a new branch), with that node's radius. Returns it, or -1.
int addBranch(Skeleton& skeleton, int node, const Eigen::Vector3d& position);

/// Removes the node and its edges. A node of two edges is bridged (its neighbours joined), so deleting a
/// node inside a chain shortens the chain instead of cutting it. The root moves to a neighbour when it was
/// this node. Node ids above it shift down by one.
bool deleteNode(Skeleton& skeleton, int node);

/// Makes `node` the root; false when it does not exist.
bool setRoot(Skeleton& skeleton, int node);

/// The nearest point of each edge to a ray (picking in a view): the edge and the parameter along it of the
/// edge point nearest the line origin + s direction, and that distance. Edge -1 for a skeleton without edges.
struct EdgeNearRay {
  int edge = -1;        ///< the nearest edge
  double t = 0;         ///< its parameter in [0, 1] from its first node
  double distance = 0;  ///< the distance between the edge point and the ray
};
/// The edge nearest the ray origin + s direction (see EdgeNearRay).
EdgeNearRay nearestEdgeToRay(const Skeleton& skeleton, const Eigen::Vector3d& origin,
                             const Eigen::Vector3d& direction);

}  // namespace medial
