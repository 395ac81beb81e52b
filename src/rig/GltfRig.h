/// \file
/// GltfRig: a rig as glTF 2.0 (.glb binary or .gltf with an embedded buffer), written with TinyGLTF.
/// Assimp's glTF 2.0 exporter takes time quadratic in the vertices (docs/measurements.md); this one is linear
/// (the same conventions as RigBones.h and the FBX writer): a node "Scene" holding the mesh's node (mesh and
/// skin) and "Armature" -> "Root" -> the bones, the skin's joints the root joint and every bone that drives a
/// vertex, their inverse bind matrices the rest pose, and per vertex at most four joints (JOINTS_0,
/// WEIGHTS_0).
#pragma once

#include "rig/RigBones.h"

#include <string>
#include <utility>
#include <vector>

namespace medial {

/// Writes the rig to `path` (binary glTF when `binary`). `influences[e]` are the (vertex, weight) pairs of
/// skeleton edge e (keptInfluences, at most four per vertex). Returns an empty string, or the problem.
std::string writeGltfRig(const Rig& rig, const std::vector<RigBone>& bones,
                         const std::vector<std::vector<std::pair<int, double>>>& influences,
                         const std::string& meshName, const std::string& path, bool binary);

}  // namespace medial
