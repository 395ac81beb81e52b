/// \file
/// FbxRig: a rig (mesh, armature, skin) as binary FBX 7.4, the records Blender's importer, Unity and Maya
/// read: Model/Geometry/NodeAttribute objects, a Skin deformer with one Cluster per weighted bone (its
/// Indexes, Weights, Transform and TransformLink), a BindPose, and the OO connections between them. Units:
/// one unit is one metre (UnitScaleFactor 100, as glTF), Y up.
#pragma once

#include "rig/RigBones.h"

#include <string>
#include <utility>
#include <vector>

namespace medial {

/// The file's bytes. `influences[e]` are the (vertex, weight) pairs of skeleton edge e (keptInfluences).
std::string fbxRigFile(const Rig& rig, const std::vector<RigBone>& bones,
                       const std::vector<std::vector<std::pair<int, double>>>& influences,
                       const std::string& meshName);

}  // namespace medial
