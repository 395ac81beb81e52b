/// \file
/// RigBones: the joints of an exported rig, shared by the glTF and FBX writers.
///
/// Chosen where the contraction paper (III.F) is silent, for what animation tools expect of a rig:
/// - One root joint, "Root", that drives no vertex; every other joint hangs under it, so the hierarchy has
///   one root as rigs from Blender, Mixamo or Unity do. With the mesh given it stands on the ground below
///   the skeleton's root node (the body centre, rig/RigRoot.h; node 0 when none was chosen), this frame's
///   Y up: below the mesh's lowest point by twice the farthest any vertex lies from the skeleton (at least
///   5 % of the mesh's height), its Y axis down, with a "Root_end" joint below it - the bone an importer
///   makes of it lies outside the mesh, so that Blender's automatic weights give it no vertex (see
///   putRootOnTheGround in RigBones.cpp). Without the mesh it sits at the root node, world axes.
/// - One bone per skeleton edge, "Bone_<edge>_<head node>_<tail node>", so that bone i is driven by weight
///   column i. Its head is the edge's end nearer the root node (breadth-first from it, then from the first
///   node of each other component), its tail the other end. Its frame sits at the head with its Y axis
///   along the bone (Blender's convention) in the rest pose.
/// - A bone's parent is the bone whose tail is its head; bones that start at the root node (or at the first
///   node of another component) hang under the root joint. An edge that closes a cycle is a bone too,
///   parented like the others.
/// - An end joint "<bone>_end" at the tail of every bone that no bone continues (the leaf bones, and the
///   bones that close a cycle), in its bone's frame, driving nothing: glTF and FBX store no bone tails, and
///   importers end a bone at its child - so every bone ends exactly at its skeleton node in Blender.
#pragma once

#include "rig/RigExport.h"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace medial {

/// One joint of an exported rig.
struct RigBone {
  std::string name;  ///< as rigBoneNames() gives it
  int edge = -1;     ///< the skeleton edge; -1 for the joints that drive nothing (root, end joints)
  int head = -1;     ///< the skeleton node the joint sits at
  int tail = -1;     ///< the skeleton node it points to (a joint that drives nothing: head again)
  int parent = -1;   ///< index in the bone list, -1 for the root joint
  Eigen::Matrix4d global = Eigen::Matrix4d::Identity();  ///< rest pose, mesh space
};

/// The root joint first, then the bones in breadth-first order, then the end joints (parents before
/// children). `ground`: the mesh's vertices in this frame, Y up, to stand the root joint below (see above).
std::vector<RigBone> buildRigBones(const Skeleton& skeleton, const Vertices* ground = nullptr);

/// The node the root joint sits at: skeleton.root, or node 0 when none was chosen.
int rigRootNode(const Skeleton& skeleton);

/// For each skeleton edge, the (vertex, weight) pairs it drives: the `maxInfluences` largest weights of
/// each vertex, renormalized to sum 1 (vertices whose weights are all zero are left out). No bone drives
/// nothing: a bone that keeps no vertex after the cap (a short bone beside longer ones) keeps its strongest
/// vertex and those where it weighs at least half as much, in place of their weakest influence; a bone no
/// heat reached takes the vertex nearest its middle with the weight of the influence it replaces.
std::vector<std::vector<std::pair<int, double>>> keptInfluences(const Rig& rig, int maxInfluences);

}  // namespace medial
