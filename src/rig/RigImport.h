/// \file
/// RigImport: reads a rig (.fbx, .glb, .gltf; Medial's or another tool's) back through Assimp as a mesh
/// and a skeleton, so that Medial opens the rigs it writes.
///
/// The skeleton, chosen where no paper speaks: a node at each joint's rest position (joints at the same
/// place, as Medial's root joint and the bones leaving one node, are one node), an edge from each joint to
/// its parent joint, and for a joint without child joints (a leaf bone: glTF and FBX store no bone length)
/// a tail along its Y axis as far as the vertices it weighs most reach. Radius of a node: the median
/// distance, to their bone's segment, of the vertices whose largest weight belongs to a bone at that node;
/// nodes without such vertices take their neighbours' mean (empty radii when the file has no weights).
#pragma once

#include "mesh/TriangleMesh.h"
#include "skeleton/Skeleton.h"

#include <string>

namespace medial {

/// A rig read from a file (any format Assimp reads).
struct ImportedRig {
  TriangleMesh mesh;  ///< every mesh of the file, in scene space, merged
  Skeleton skeleton;  ///< empty when the file has no joints
  int joints = 0;     ///< joints in the file
  std::string error;  ///< empty on success
};

/// The mesh and the joints of the rig at `path` (glTF, FBX, Collada, ...).
ImportedRig importRig(const std::string& path);

}  // namespace medial
