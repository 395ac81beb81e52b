// RigExport: section III.F of the contraction paper. Packs the skinned mesh and its skeleton into a rig
// file that Blender, Maya or 3ds Max open: glTF 2.0 (.glb binary, .gltf text) or FBX (binary; "fbxa" is
// FBX's ASCII flavour), written through Assimp.
//
// The rig, chosen here where the paper is silent:
// - One bone per skeleton edge, so bone i is driven by weight column i. Its head is the edge's end nearer
//   the root (breadth-first from the skeleton's root, then from the first node of each other component),
//   its tail the other end. The bone's frame sits at the head with its Y axis along the bone (the
//   Blender convention), in the rest pose of the input.
// - Hierarchy: a bone's parent is the bone whose tail is its head; bones that start at a root hang under
//   an "Armature" node. An edge that closes a cycle is a bone too, parented like the others.
// - At most `maxInfluences` bones per vertex (default 4: glTF's JOINTS_0/WEIGHTS_0 carry four, as do
//   most game engines), the largest kept and renormalized to sum 1.
#pragma once

#include "mesh/TriangleMesh.h"
#include "skeleton/Skeleton.h"

#include <string>
#include <vector>

namespace medial {

struct Rig {
  TriangleMesh mesh;
  Skeleton skeleton;        // nodes, edges (bones) and root
  Eigen::MatrixXd weights;  // (mesh vertices x skeleton edges), rows summing to 1
};

struct RigExportOptions {
  int maxInfluences = 4;
  std::string meshName = "Mesh";
};

// The Assimp exporter id for a file name: .glb -> glb2, .gltf -> gltf2, .fbx -> fbx; empty if unknown.
std::string rigFormatForFile(const std::string& path);

// Writes the rig to `path` in Assimp's `format` (glb2, gltf2, fbx, fbxa, collada...). Returns an empty
// string on success, else the problem (bad rig, unknown format, Assimp's error).
std::string exportRig(const Rig& rig, const std::string& path, const std::string& format,
                      const RigExportOptions& options = {});

// Bone names in export order ("Bone_<edge>_<head node>_<tail node>"): what a DCC tool will show.
std::vector<std::string> rigBoneNames(const Skeleton& skeleton);

// What an exported rig holds when read back (for tests and the CLI's report).
struct RigSummary {
  int bones = 0;  // bones that influence the mesh
  int vertices = 0;
  int faces = 0;
  double maxWeightSumError = 0;  // max over vertices of |sum of weights - 1|
  int unweightedVertices = 0;    // vertices no bone influences
  std::string error;
};
RigSummary readRigSummary(const std::string& path);

}  // namespace medial
