// RigBones: the joints of an exported rig, shared by the glTF and FBX writers.
//
// Chosen where the contraction paper (III.F) is silent, for what animation tools expect of a rig:
// - One root joint, "Root", at the skeleton's root node (the node the contraction chose: the highest
//   degree, then the most mesh vertices; node 0 when none was chosen). It drives no vertex; every other
//   joint hangs under it, so the hierarchy has one root as rigs from Blender, Mixamo or Unity do.
// - One bone per skeleton edge, "Bone_<edge>_<head node>_<tail node>", so that bone i is driven by weight
//   column i. Its head is the edge's end nearer the root (breadth-first from the root, then from the first
//   node of each other component), its tail the other end. Its frame sits at the head with its Y axis
//   along the bone (Blender's convention) in the rest pose of the input; the root joint's frame is the
//   world's axes at the root node.
// - A bone's parent is the bone whose tail is its head; bones that start at the root node (or at the first
//   node of another component) hang under the root joint. An edge that closes a cycle is a bone too,
//   parented like the others.
#pragma once

#include "rig/RigExport.h"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace medial {

struct RigBone {
  std::string name;
  int edge = -1;                                         // the skeleton edge, -1 for the root joint
  int head = -1, tail = -1;                              // skeleton nodes (the root joint: its node twice)
  int parent = -1;                                       // index in the bone list, -1 for the root joint
  Eigen::Matrix4d global = Eigen::Matrix4d::Identity();  // rest pose, mesh space
};

// The root joint first, then the bones in breadth-first order (parents before children).
std::vector<RigBone> buildRigBones(const Skeleton& skeleton);

// The node the root joint sits at: skeleton.root, or node 0 when none was chosen.
int rigRootNode(const Skeleton& skeleton);

// For each skeleton edge, the (vertex, weight) pairs it drives: the `maxInfluences` largest weights of
// each vertex, renormalized to sum 1 (vertices whose weights are all zero are left out).
std::vector<std::vector<std::pair<int, double>>> keptInfluences(const Rig& rig, int maxInfluences);

}  // namespace medial
