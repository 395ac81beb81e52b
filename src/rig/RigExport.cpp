#include "rig/RigExport.h"

#include "rig/FbxRig.h"
#include "rig/GltfRig.h"
#include "rig/RigBones.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <cmath>
#include <map>
#include <memory>

namespace medial {

namespace {

using Transform = Eigen::Matrix4d;

aiMatrix4x4 toAssimp(const Transform& m) {
  return aiMatrix4x4(float(m(0, 0)), float(m(0, 1)), float(m(0, 2)), float(m(0, 3)),  //
                     float(m(1, 0)), float(m(1, 1)), float(m(1, 2)), float(m(1, 3)),  //
                     float(m(2, 0)), float(m(2, 1)), float(m(2, 2)), float(m(2, 3)),  //
                     float(m(3, 0)), float(m(3, 1)), float(m(3, 2)), float(m(3, 3)));
}

aiNode* newNode(const std::string& name, const Transform& local, aiNode* parent) {
  auto* node = new aiNode(name);
  node->mTransformation = toAssimp(local);
  node->mParent = parent;
  return node;
}

void setChildren(aiNode* node, const std::vector<aiNode*>& children) {
  node->mNumChildren = unsigned(children.size());
  node->mChildren = children.empty() ? nullptr : new aiNode*[children.size()];
  std::copy(children.begin(), children.end(), node->mChildren);
}

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

// The mesh with one aiBone per joint that influences it, and the root joint (no weights: it must be a
// joint of the skin for glTF importers to make it a bone).
aiMesh* buildMesh(const Rig& rig, const std::vector<RigBone>& bones, const RigExportOptions& options) {
  const Eigen::Index n = rig.mesh.vertices.rows();
  auto* mesh = new aiMesh;
  mesh->mName = options.meshName;
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mMaterialIndex = 0;
  mesh->mNumVertices = unsigned(n);
  mesh->mVertices = new aiVector3D[size_t(n)];
  for (Eigen::Index v = 0; v < n; ++v)
    mesh->mVertices[v] = aiVector3D(float(rig.mesh.vertices(v, 0)), float(rig.mesh.vertices(v, 1)),
                                    float(rig.mesh.vertices(v, 2)));
  mesh->mNumFaces = unsigned(rig.mesh.faces.rows());
  mesh->mFaces = new aiFace[mesh->mNumFaces];
  for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
    mesh->mFaces[f].mNumIndices = 3;
    mesh->mFaces[f].mIndices = new unsigned[3];
    for (int c = 0; c < 3; ++c) mesh->mFaces[f].mIndices[c] = unsigned(rig.mesh.faces(f, c));
  }
  const auto influences = keptInfluences(rig, options.maxInfluences);
  std::vector<aiBone*> meshBones;
  for (const RigBone& bone : bones) {
    if (bone.edge >= 0 && influences[size_t(bone.edge)].empty()) continue;
    auto* b = new aiBone;
    b->mName = bone.name;
    b->mOffsetMatrix = toAssimp(bone.global.inverse());  // mesh space -> bone space (rest pose)
    if (bone.edge >= 0) {
      const auto& weights = influences[size_t(bone.edge)];
      b->mNumWeights = unsigned(weights.size());
      b->mWeights = new aiVertexWeight[weights.size()];
      for (size_t k = 0; k < weights.size(); ++k)
        b->mWeights[k] = aiVertexWeight(unsigned(weights[k].first), float(weights[k].second));
    }
    meshBones.push_back(b);
  }
  mesh->mNumBones = unsigned(meshBones.size());
  mesh->mBones = new aiBone*[meshBones.size()];
  std::copy(meshBones.begin(), meshBones.end(), mesh->mBones);
  return mesh;
}

// Binary FBX, written by Medial (rig/FbxRig.h): Assimp's FBX exporter writes files Blender refuses.
std::string writeFbx(const Rig& rig, const std::vector<RigBone>& bones, const std::string& path,
                     const RigExportOptions& options) {
  const std::string bytes =
      fbxRigFile(rig, bones, keptInfluences(rig, options.maxInfluences), options.meshName);
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file || !file.write(bytes.data(), std::streamsize(bytes.size())) || !file.flush())
    return "cannot write the rig to " + path + ": " + std::strerror(errno);
  return {};
}

}  // namespace

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
  const std::vector<RigBone> bones = buildRigBones(rig.skeleton);
  if (format == "fbx") return writeFbx(rig, bones, path, options);
  if (format == "glb2" || format == "gltf2")  // TinyGLTF: Assimp's glTF exporter is quadratic in the vertices
    return writeGltfRig(rig, bones, keptInfluences(rig, std::min(options.maxInfluences, 4)), options.meshName,
                        path, format == "glb2");

  auto scene = std::make_unique<aiScene>();
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial* [1] { new aiMaterial };
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh* [1] { buildMesh(rig, bones, options) };

  // Node tree: Scene -> {Mesh, Armature -> Root -> bones by hierarchy}.
  scene->mRootNode = new aiNode("Scene");
  aiNode* meshNode = newNode(options.meshName, Transform::Identity(), scene->mRootNode);
  meshNode->mNumMeshes = 1;
  meshNode->mMeshes = new unsigned[1]{0};
  aiNode* armature = newNode("Armature", Transform::Identity(), scene->mRootNode);
  setChildren(scene->mRootNode, {meshNode, armature});
  std::vector<aiNode*> boneNodes(bones.size());
  std::vector<std::vector<aiNode*>> children(bones.size());
  for (size_t b = 0; b < bones.size(); ++b) {
    const RigBone& bone = bones[b];
    const Transform parentGlobal =
        bone.parent < 0 ? Transform::Identity() : bones[size_t(bone.parent)].global;
    aiNode* parent = bone.parent < 0 ? armature : boneNodes[size_t(bone.parent)];
    boneNodes[b] = newNode(bone.name, parentGlobal.inverse() * bone.global, parent);
    if (bone.parent >= 0) children[size_t(bone.parent)].push_back(boneNodes[b]);
  }
  for (size_t b = 0; b < bones.size(); ++b) setChildren(boneNodes[b], children[b]);
  setChildren(armature, {boneNodes[0]});

  Assimp::Exporter exporter;
  if (exporter.Export(scene.get(), format, path) != AI_SUCCESS) {
    const std::string error = exporter.GetErrorString();
    return "cannot write the rig as " + format + ": " +
           (error.empty() ? "unknown format or I/O error" : error);
  }
  return {};
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
