#include "rig/RigExport.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <memory>
#include <numeric>

namespace medial {

namespace {

using Transform = Eigen::Matrix4d;

aiMatrix4x4 toAssimp(const Transform& m) {
  return aiMatrix4x4(float(m(0, 0)), float(m(0, 1)), float(m(0, 2)), float(m(0, 3)),  //
                     float(m(1, 0)), float(m(1, 1)), float(m(1, 2)), float(m(1, 3)),  //
                     float(m(2, 0)), float(m(2, 1)), float(m(2, 2)), float(m(2, 3)),  //
                     float(m(3, 0)), float(m(3, 1)), float(m(3, 2)), float(m(3, 3)));
}

// The bone frame at `head` with Y along head -> tail.
Transform boneFrame(const Eigen::Vector3d& head, const Eigen::Vector3d& tail) {
  Eigen::Vector3d direction = tail - head;
  if (direction.squaredNorm() == 0) direction = Eigen::Vector3d::UnitY();
  const Eigen::Matrix3d rotation =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitY(), direction.normalized()).toRotationMatrix();
  Transform frame = Transform::Identity();
  frame.topLeftCorner<3, 3>() = rotation;
  frame.topRightCorner<3, 1>() = head;
  return frame;
}

struct Bone {
  int edge;
  int head, tail;
  int parent = -1;  // bone index, -1 under the armature
  Transform global;
};

// Orients every edge away from the roots (breadth-first) and links each bone to the bone ending at its head.
std::vector<Bone> buildBones(const Skeleton& skeleton) {
  const int n = skeleton.nodeCount();
  std::vector<std::vector<std::pair<int, int>>> adjacent(static_cast<size_t>(n));  // (neighbour, edge)
  for (int e = 0; e < skeleton.edgeCount(); ++e) {
    adjacent[size_t(skeleton.edges[size_t(e)][0])].push_back({skeleton.edges[size_t(e)][1], e});
    adjacent[size_t(skeleton.edges[size_t(e)][1])].push_back({skeleton.edges[size_t(e)][0], e});
  }
  std::vector<int> depth(static_cast<size_t>(n), -1), incomingBone(static_cast<size_t>(n), -1);
  std::vector<Bone> bones;
  std::vector<bool> edgeDone(static_cast<size_t>(skeleton.edgeCount()), false);
  std::vector<int> starts;
  if (skeleton.root >= 0 && skeleton.root < n) starts.push_back(skeleton.root);
  for (int v = 0; v < n; ++v) starts.push_back(v);
  for (int start : starts) {
    if (depth[size_t(start)] >= 0) continue;
    depth[size_t(start)] = 0;
    std::deque<int> queue{start};
    while (!queue.empty()) {
      const int u = queue.front();
      queue.pop_front();
      for (const auto& [v, e] : adjacent[size_t(u)]) {
        if (edgeDone[size_t(e)]) continue;
        edgeDone[size_t(e)] = true;
        Bone bone{e, u, v, incomingBone[size_t(u)],
                  boneFrame(skeleton.nodes[size_t(u)], skeleton.nodes[size_t(v)])};
        bones.push_back(bone);
        if (depth[size_t(v)] <
            0) {  // a tree edge; otherwise it closes a cycle and v keeps its own parent bone
          depth[size_t(v)] = depth[size_t(u)] + 1;
          incomingBone[size_t(v)] = int(bones.size()) - 1;
          queue.push_back(v);
        }
      }
    }
  }
  return bones;
}

std::string boneName(const Bone& bone) {
  return "Bone_" + std::to_string(bone.edge) + "_" + std::to_string(bone.head) + "_" +
         std::to_string(bone.tail);
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

// The mesh with one aiBone per skeleton edge that influences it.
aiMesh* buildMesh(const Rig& rig, const std::vector<Bone>& bones, const RigExportOptions& options) {
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

  // The largest maxInfluences weights of each vertex, renormalized.
  std::vector<std::vector<aiVertexWeight>> perBone(static_cast<size_t>(rig.skeleton.edgeCount()));
  std::vector<int> order(static_cast<size_t>(rig.weights.cols()));
  for (Eigen::Index v = 0; v < n; ++v) {
    std::iota(order.begin(), order.end(), 0);
    const size_t keep = std::min(order.size(), size_t(std::max(1, options.maxInfluences)));
    std::partial_sort(order.begin(), order.begin() + long(keep), order.end(),
                      [&](int a, int b) { return rig.weights(v, a) > rig.weights(v, b); });
    double sum = 0;
    for (size_t k = 0; k < keep; ++k) sum += std::max(0.0, rig.weights(v, order[k]));
    if (!(sum > 0)) continue;
    for (size_t k = 0; k < keep; ++k) {
      const double w = rig.weights(v, order[k]) / sum;
      if (w > 0) perBone[size_t(order[k])].push_back(aiVertexWeight(unsigned(v), float(w)));
    }
  }
  std::vector<aiBone*> meshBones;
  for (const Bone& bone : bones) {
    auto& weights = perBone[size_t(bone.edge)];
    if (weights.empty()) continue;
    auto* b = new aiBone;
    b->mName = boneName(bone);
    b->mOffsetMatrix = toAssimp(bone.global.inverse());  // mesh space -> bone space (rest pose)
    b->mNumWeights = unsigned(weights.size());
    b->mWeights = new aiVertexWeight[weights.size()];
    std::copy(weights.begin(), weights.end(), b->mWeights);
    meshBones.push_back(b);
  }
  mesh->mNumBones = unsigned(meshBones.size());
  if (!meshBones.empty()) {  // aiMesh frees mBones only when it counts bones (a leak LeakSanitizer found)
    mesh->mBones = new aiBone*[meshBones.size()];
    std::copy(meshBones.begin(), meshBones.end(), mesh->mBones);
  }
  return mesh;
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
  for (const Bone& bone : buildBones(skeleton)) names.push_back(boneName(bone));
  return names;
}

std::string exportRig(const Rig& rig, const std::string& path, const std::string& format,
                      const RigExportOptions& options) {
  if (std::string problem = checkRig(rig); !problem.empty()) return problem;
  const std::vector<Bone> bones = buildBones(rig.skeleton);

  auto scene = std::make_unique<aiScene>();
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial* [1] { new aiMaterial };
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh* [1] { buildMesh(rig, bones, options) };

  // Node tree: Root -> {Mesh, Armature -> bones by hierarchy}.
  scene->mRootNode = new aiNode("Root");
  aiNode* meshNode = newNode(options.meshName, Transform::Identity(), scene->mRootNode);
  meshNode->mNumMeshes = 1;
  meshNode->mMeshes = new unsigned[1]{0};
  aiNode* armature = newNode("Armature", Transform::Identity(), scene->mRootNode);
  setChildren(scene->mRootNode, {meshNode, armature});

  std::vector<aiNode*> boneNodes(bones.size());
  std::vector<std::vector<aiNode*>> children(bones.size());
  std::vector<aiNode*> armatureChildren;
  for (size_t b = 0; b < bones.size(); ++b) {
    const Bone& bone = bones[b];
    const Transform parentGlobal =
        bone.parent < 0 ? Transform::Identity() : bones[size_t(bone.parent)].global;
    aiNode* parent = bone.parent < 0 ? armature : boneNodes[size_t(bone.parent)];
    boneNodes[b] = newNode(boneName(bone), parentGlobal.inverse() * bone.global, parent);
    (bone.parent < 0 ? armatureChildren : children[size_t(bone.parent)]).push_back(boneNodes[b]);
  }
  for (size_t b = 0; b < bones.size(); ++b) setChildren(boneNodes[b], children[b]);
  setChildren(armature, armatureChildren);

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
      boneNames[mesh->mBones[b]->mName.C_Str()] = true;
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
