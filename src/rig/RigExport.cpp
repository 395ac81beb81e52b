#include "rig/RigExport.h"

#include "rig/FbxRig.h"
#include "rig/GltfRig.h"
#include "rig/RigBones.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <cmath>

namespace medial {

namespace {

std::string checkRig(const Rig& rig) {
  if (rig.mesh.faces.rows() == 0) return "the mesh has no triangles";
  if (rig.skeleton.edgeCount() == 0) return "the skeleton has no bones (edges)";
  if (rig.weights.rows() != rig.mesh.vertices.rows() || rig.weights.cols() != rig.skeleton.edgeCount())
    return "the weights are " + std::to_string(rig.weights.rows()) + " x " +
           std::to_string(rig.weights.cols()) +
           ", expected vertices x bones = " + std::to_string(rig.mesh.vertices.rows()) + " x " +
           std::to_string(rig.skeleton.edgeCount());
  for (const auto& e : rig.skeleton.edges)
    if (e[0] < 0 || e[1] < 0 || e[0] >= rig.skeleton.nodeCount() || e[1] >= rig.skeleton.nodeCount())
      return "a skeleton edge refers to a node that does not exist";
  // Found by fuzzing (tests/fuzz/rig.cpp): NaN or negative weights gave a rig without bones.
  for (Eigen::Index v = 0; v < rig.weights.rows(); ++v)
    for (Eigen::Index b = 0; b < rig.weights.cols(); ++b)
      if (!(rig.weights(v, b) >= 0) || !std::isfinite(rig.weights(v, b)))
        return "the weight of vertex " + std::to_string(v) + " for bone " + std::to_string(b) + " is " +
               std::to_string(rig.weights(v, b)) + " (weights are finite and >= 0)";
  return {};
}

// Binary FBX, written by Medial (rig/FbxRig.h): Assimp's FBX exporter writes files Blender refuses.
std::string writeFbx(const Rig& rig, const std::vector<RigBone>& bones,
                     const std::vector<std::vector<std::pair<int, double>>>& influences,
                     const std::string& path, const RigExportOptions& options) {
  const std::string bytes = fbxRigFile(rig, bones, influences, options.meshName);
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file || !file.write(bytes.data(), std::streamsize(bytes.size())) || !file.flush())
    return "cannot write the rig to " + path + ": " + std::strerror(errno);
  return {};
}

// The rig's mesh and skeleton in the file's frame: turned so that its up axis is +Y, scaled to metres.
std::string orientedForExport(const Rig& rig, const RigExportOptions& options, Rig& turned) {
  Eigen::Matrix3d rotation;
  if (!upAxisRotation(options.upAxis, rotation))
    return "the up axis is '" + options.upAxis + "': it is one of x, y, z, -x, -y, -z";
  if (!(options.scale > 0) || !std::isfinite(options.scale))
    return "the scale is " + std::to_string(options.scale) + ": it is a positive number";
  const Eigen::Matrix3d transform = options.scale * rotation;
  turned.mesh.faces = rig.mesh.faces;
  turned.mesh.vertices = rig.mesh.vertices * transform.transpose();
  turned.skeleton = rig.skeleton;
  for (Eigen::Vector3d& node : turned.skeleton.nodes) node = transform * node;
  return {};  // without the weights (up to gigabytes): the influences come from `rig`, in any frame the same
}

}  // namespace

bool upAxisRotation(const std::string& upAxis, Eigen::Matrix3d& rotation) {
  // Each row is where the file's x, y, z come from: the file's y is the mesh's up axis.
  static const std::map<std::string, Eigen::Matrix3d> rotations = [] {
    std::map<std::string, Eigen::Matrix3d> r;
    r["y"] = Eigen::Matrix3d::Identity();
    r["-y"] = Eigen::Vector3d(1, -1, -1).asDiagonal();
    r["z"] = (Eigen::Matrix3d() << 1, 0, 0, 0, 0, 1, 0, -1, 0).finished();
    r["-z"] = (Eigen::Matrix3d() << 1, 0, 0, 0, 0, -1, 0, 1, 0).finished();
    r["x"] = (Eigen::Matrix3d() << 0, -1, 0, 1, 0, 0, 0, 0, 1).finished();
    r["-x"] = (Eigen::Matrix3d() << 0, 1, 0, -1, 0, 0, 0, 0, 1).finished();
    return r;
  }();
  const auto found = rotations.find(upAxis);
  if (found == rotations.end()) return false;
  rotation = found->second;
  return true;
}

std::string rigFormatForFile(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  std::string extension = dot == std::string::npos ? "" : path.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (extension == ".glb") return "glb2";
  if (extension == ".gltf") return "gltf2";
  if (extension == ".fbx") return "fbx";
  return {};
}

std::vector<std::string> rigBoneNames(const Skeleton& skeleton) {
  std::vector<std::string> names;
  for (const RigBone& bone : buildRigBones(skeleton)) names.push_back(bone.name);
  return names;
}

std::string exportRig(const Rig& rig, const std::string& path, const std::string& format,
                      const RigExportOptions& options) {
  if (std::string problem = checkRig(rig); !problem.empty()) return problem;
  Rig turned;
  if (std::string problem = orientedForExport(rig, options, turned); !problem.empty()) return problem;
  const std::vector<RigBone> bones = buildRigBones(turned.skeleton, &turned.mesh.vertices);
  if (format == "fbx")
    return writeFbx(turned, bones, keptInfluences(rig, options.maxInfluences), path, options);
  if (format == "glb2" || format == "gltf2")  // TinyGLTF: Assimp's glTF exporter is quadratic in the vertices
    return writeGltfRig(turned, bones, keptInfluences(rig, std::min(options.maxInfluences, 4)),
                        options.meshName, path, format == "glb2");
  return "cannot write a rig as '" + format + "': the formats are glb2, gltf2 and fbx";
}

RigSummary readRigSummary(const std::string& path) {
  RigSummary summary;
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, 0);
  if (!scene) {
    summary.error = importer.GetErrorString();
    return summary;
  }
  std::map<std::string, bool> boneNames;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    std::vector<double> sums(mesh->mNumVertices, 0.0);
    for (unsigned b = 0; b < mesh->mNumBones; ++b) {
      const aiBone* bone = mesh->mBones[b];
      if (std::any_of(bone->mWeights, bone->mWeights + bone->mNumWeights,
                      [](const aiVertexWeight& w) { return w.mWeight > 0; }))
        boneNames[bone->mName.C_Str()] = true;  // not the root joint (glTF pads influences with weight 0)
      for (unsigned w = 0; w < mesh->mBones[b]->mNumWeights; ++w)
        sums[mesh->mBones[b]->mWeights[w].mVertexId] += mesh->mBones[b]->mWeights[w].mWeight;
    }
    for (double sum : sums) {
      if (sum == 0) ++summary.unweightedVertices;
      summary.maxWeightSumError = std::max(summary.maxWeightSumError, std::abs(sum - 1.0));
    }
    summary.vertices += int(mesh->mNumVertices);
    summary.faces += int(mesh->mNumFaces);
  }
  summary.bones = int(boneNames.size());
  return summary;
}

}  // namespace medial
