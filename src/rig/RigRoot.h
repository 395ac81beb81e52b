/// \file
/// RigRoot: the node a rig hangs from. A rigger roots a figure at its hips (a quadruped at its hips or the
/// middle of its spine): the node the body moves from, never a hand, a foot or a finger. Chosen from the
/// skeleton and the mesh together:
/// - the central nodes: those whose farthest node along the skeleton (its eccentricity, over edge lengths)
///   is at most `kCentralShare` (0.65) of the longest path, in the component with the longest edges in
///   all (a tree's centre has half the longest path; the share reaches the hips and the chest of a figure,
///   at about 0.6, and no limb's end);
/// - among them the branch nodes (three or more edges: where legs or arms leave the body), else all;
/// - of those, the nearest to the mesh's volume centroid (mesh/MeshGeometry.h), the figure's middle.
#pragma once

#include "mesh/TriangleMesh.h"
#include "skeleton/Skeleton.h"

namespace medial {

/// Farthest-node share of the longest path that makes a node central.
constexpr double kCentralShare = 0.65;

/// The body-centre root described above; -1 for a skeleton without nodes. With an empty mesh the central
/// node nearest the skeleton's own centre of edge length.
int bodyCentreNode(const Skeleton& skeleton, const TriangleMesh& mesh);

/// The middle node of the longest shortest path of the skeleton's longest component (by edge length);
/// -1 for a skeleton without nodes.
int centralNode(const Skeleton& skeleton);

/// Each node's distance along the edges to the farthest node of its component (exact on a tree: the larger
/// of its distances to the two ends of a longest path) and that longest path's length (in `longest`).
std::vector<double> nodeEccentricities(const Skeleton& skeleton, double& longest);

}  // namespace medial
