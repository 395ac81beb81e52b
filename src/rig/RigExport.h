/// \file
/// RigExport: section III.F of the contraction paper. Packs the skinned mesh and its skeleton into a rig
/// file that Blender, Maya or Unity open: glTF 2.0 (.glb binary, .gltf text) written with TinyGLTF
/// (rig/GltfRig.h), binary FBX 7.4 written by Medial (rig/FbxRig.h; Assimp's FBX exporter writes files
/// Blender refuses). The joints, their names, frames and hierarchy (one root) are rig/RigBones.h's. At most
/// `maxInfluences` bones per vertex (default 4: glTF's JOINTS_0/WEIGHTS_0 carry four, as do most game
/// engines), the largest kept and renormalized to sum 1.
#pragma once

#include "mesh/TriangleMesh.h"
#include "skeleton/Skeleton.h"

#include <string>
#include <vector>

namespace medial {

/// A skinned mesh: the mesh, the skeleton whose edges are its bones, and the weights.
struct Rig {
  TriangleMesh mesh;        ///< in the mesh's own frame and units
  Skeleton skeleton;        ///< nodes, edges (bones) and root
  Eigen::MatrixXd weights;  ///< (mesh vertices x skeleton edges), rows summing to 1
};

/// How a rig is written: influences per vertex, names, up axis and scale.
struct RigExportOptions {
  int maxInfluences = 4;          ///< the largest weights kept per vertex (renormalized)
  std::string meshName = "Mesh";  ///< the mesh object's name in the file
  /// The mesh's own up axis: x, y, z, -x, -y or -z. The rig is turned so that it points up in the file
  /// (glTF's and this FBX's +Y; Blender turns +Y into its +Z on import): a Z-up scan stands. Default y.
  std::string upAxis = "y";
  double scale = 1.0;  ///< mesh units to the file's metres: 0.01 for a mesh in centimetres
};

/// The rotation that takes `upAxis` (x, y, z, -x, -y, -z) to +Y: a proper rotation, the identity for y, for
/// z the usual Z-up to Y-up turn (x, y, z) -> (x, z, -y). False for an unknown axis.
bool upAxisRotation(const std::string& upAxis, Eigen::Matrix3d& rotation);

/// The format for a file name: .glb -> glb2, .gltf -> gltf2, .fbx -> fbx; empty if unknown.
std::string rigFormatForFile(const std::string& path);

/// Writes the rig to `path` as `format`: fbx (Medial's binary FBX), glb2 or gltf2 (TinyGLTF), its mesh and
/// skeleton turned and scaled by the options (the Rig itself stays in the mesh's frame). Returns an empty
/// string on success, else the problem (bad rig or options, unknown format, I/O).
std::string exportRig(const Rig& rig, const std::string& path, const std::string& format,
                      const RigExportOptions& options = {});

/// Joint names in export order ("Root", then "Bone_<edge>_<head node>_<tail node>"): what a DCC shows.
std::vector<std::string> rigBoneNames(const Skeleton& skeleton);

/// What an exported rig holds when read back (for tests and the CLI's report).
struct RigSummary {
  int bones = 0;                 ///< bones that influence the mesh
  int vertices = 0;              ///< vertices of the file's meshes
  int faces = 0;                 ///< their faces
  double maxWeightSumError = 0;  ///< max over vertices of |sum of weights - 1|
  int unweightedVertices = 0;    ///< vertices no bone influences
  std::string error;             ///< why the work failed; empty on success
};
/// Reads the rig at `path` back (Assimp) and summarizes it; `error` says why it could not.
RigSummary readRigSummary(const std::string& path);

}  // namespace medial
