/// \file
/// PartConnection: sub-skeleton connection of the sketch skeletonization (Ma et al. 2021, §3.2, Figs. 8-9).
///
/// Parts are taken in modelling order. Each part's shape is approximated by balls at its joints (radius
/// = the joint's Radius) and cones along its bones (radius interpolated linearly). A later part intersects
/// an earlier one when one of its terminal or junction joints (its candidates; a lone node counts) lies in
/// that cylinder-ball region. It is then attached to the earlier part with the closest candidate/bone pair
/// by eq. (3): inside the bone's influence region (between the planes through its ends perpendicular to it)
/// the bone is split at the foot of the perpendicular and a bone joins the new joint to the candidate
/// ("bone split event"); outside, a bone joins the candidate to the nearer end joint ("joint connect
/// event"). When several earlier parts intersect the new one, the closest attachment wins. A part that
/// intersects no earlier part is a root. The result is a forest whose trees follow the modelling order.
#pragma once

#include "sketch/SketchGraph.h"

#include <vector>

namespace medial {

/// How a part hangs from an earlier one (eq. 3).
struct PartAttachment {
  int parent = -1;         ///< the part attached to (-1: a root)
  int childJoint = -1;     ///< node ids in the connected graph
  int parentJoint = -1;    ///< existing joint (joint connect) or the joint created on the split bone
  bool boneSplit = false;  ///< true: the parent's bone was split to make the joint
  double distance = 0;     ///< eq. (3)
};

/// Shortest distance of eq. (3) from `joint` to the bone [a, b]; `t` receives the foot's parameter in
/// [0, 1] when the joint is in the influence region, or -1 (nearer end a) / 2 (nearer end b) otherwise.
double boneDistance(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& joint,
                    double& t);

/// Whether `point` lies in the cylinder-ball region of the nodes and edges of part `part` in `graph`.
bool insideCylinderBall(const SketchGraph& graph, int part, const Eigen::Vector3d& point);

/// Connects the parts of `graph` (nodes labelled 0..partCount-1, each part's own bones already present)
/// in modelling order; returns one attachment per part.
std::vector<PartAttachment> connectParts(SketchGraph& graph, int partCount);

}  // namespace medial
