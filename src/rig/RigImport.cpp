#include "rig/RigImport.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

namespace medial {

namespace {

Eigen::Matrix4d toEigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d e;
  e << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return e;
}

struct Walk {
  std::map<const aiNode*, Eigen::Matrix4d> global;
  void visit(const aiNode* node, const Eigen::Matrix4d& parent) {
    const Eigen::Matrix4d g = parent * toEigen(node->mTransformation);
    global[node] = g;
    for (unsigned c = 0; c < node->mNumChildren; ++c) visit(node->mChildren[c], g);
  }
};

double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

}  // namespace

ImportedRig importRig(const std::string& path) {
  ImportedRig rig;
  Assimp::Importer importer;
  // Assimp's FBX importer gives each face corner a vertex of its own: joined again (weights follow).
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (!scene || !scene->mRootNode) {
    rig.error = importer.GetErrorString();
    if (rig.error.empty()) rig.error = "not a scene Assimp can read";
    return rig;
  }
  Walk walk;
  walk.visit(scene->mRootNode, Eigen::Matrix4d::Identity());

  // The meshes in scene space, merged; the joints and, per vertex, its largest weight's joint.
  std::set<std::string> jointNames;
  std::vector<std::pair<std::string, double>> strongest;  // per merged vertex: (joint, weight)
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
  std::function<void(const aiNode*)> addMeshes = [&](const aiNode* node) {
    const Eigen::Matrix4d& g = walk.global[node];
    for (unsigned k = 0; k < node->mNumMeshes; ++k) {
      const aiMesh* mesh = scene->mMeshes[node->mMeshes[k]];
      const int first = int(vertices.size());
      for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
        const aiVector3D& p = mesh->mVertices[v];
        vertices.push_back((g * Eigen::Vector4d(p.x, p.y, p.z, 1)).head<3>());
      }
      strongest.resize(vertices.size(), {std::string(), 0.0});
      for (unsigned f = 0; f < mesh->mNumFaces; ++f)
        if (mesh->mFaces[f].mNumIndices == 3)
          faces.emplace_back(first + int(mesh->mFaces[f].mIndices[0]),
                             first + int(mesh->mFaces[f].mIndices[1]),
                             first + int(mesh->mFaces[f].mIndices[2]));
      for (unsigned b = 0; b < mesh->mNumBones; ++b) {
        const aiBone* bone = mesh->mBones[b];
        jointNames.insert(bone->mName.C_Str());
        for (unsigned w = 0; w < bone->mNumWeights; ++w) {
          auto& s = strongest[size_t(first) + bone->mWeights[w].mVertexId];
          if (bone->mWeights[w].mWeight > s.second) s = {bone->mName.C_Str(), bone->mWeights[w].mWeight};
        }
      }
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c) addMeshes(node->mChildren[c]);
  };
  addMeshes(scene->mRootNode);
  if (faces.empty()) {
    rig.error = "the file holds no triangles";
    return rig;
  }
  rig.mesh.vertices.resize(Eigen::Index(vertices.size()), 3);
  for (size_t v = 0; v < vertices.size(); ++v)
    rig.mesh.vertices.row(Eigen::Index(v)) = vertices[v].transpose();
  rig.mesh.faces.resize(Eigen::Index(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) rig.mesh.faces.row(Eigen::Index(f)) = faces[f].transpose();

  // Joints: the skin's bones and their ancestors below the first common one that is not a joint.
  std::vector<const aiNode*> joints;
  std::map<const aiNode*, int> jointIndex;
  for (const auto& [node, global] : walk.global)
    if (jointNames.count(node->mName.C_Str())) jointIndex[node] = 0;
  for (auto it = jointIndex.begin(); it != jointIndex.end(); ++it) {
    // Medial's and Blender's root joints drive nothing: a parent of a joint whose name says so is one too.
    for (const aiNode* p = it->first->mParent; p && !jointIndex.count(p); p = p->mParent)
      if (std::string(p->mName.C_Str()) == "Root") jointIndex[p] = 0;
  }
  for (auto& [node, index] : jointIndex) {
    index = int(joints.size());
    joints.push_back(node);
  }
  rig.joints = int(joints.size());
  if (joints.empty()) return rig;

  // Nodes: joint positions, the same place once.
  Skeleton& s = rig.skeleton;
  std::vector<int> nodeOf(joints.size());
  const double size =
      (rig.mesh.vertices.colwise().maxCoeff() - rig.mesh.vertices.colwise().minCoeff()).norm();
  auto nodeAt = [&](const Eigen::Vector3d& p) {
    for (int n = 0; n < s.nodeCount(); ++n)
      if ((s.nodes[size_t(n)] - p).norm() <= 1e-6 * size) return n;
    s.nodes.push_back(p);
    return s.nodeCount() - 1;
  };
  for (size_t j = 0; j < joints.size(); ++j)
    nodeOf[j] = nodeAt(walk.global[joints[j]].topRightCorner<3, 1>());
  std::set<std::pair<int, int>> edges;
  std::vector<bool> hasChild(joints.size(), false);
  std::vector<std::pair<int, int>> segmentOf(joints.size(), {-1, -1});  // joint -> (head node, tail node)
  for (size_t j = 0; j < joints.size(); ++j) {
    const aiNode* parent = joints[j]->mParent;
    if (parent && jointIndex.count(parent)) {
      const int p = jointIndex[parent];
      hasChild[size_t(p)] = true;
      if (nodeOf[size_t(p)] != nodeOf[j]) {
        edges.insert({std::min(nodeOf[size_t(p)], nodeOf[j]), std::max(nodeOf[size_t(p)], nodeOf[j])});
        segmentOf[size_t(p)] = {nodeOf[size_t(p)], nodeOf[j]};
      }
    }
  }
  // Leaf bones: a tail along Y as far as their vertices reach.
  std::map<std::string, std::vector<int>> verticesOf;
  for (size_t v = 0; v < strongest.size(); ++v)
    if (!strongest[v].first.empty()) verticesOf[strongest[v].first].push_back(int(v));
  for (size_t j = 0; j < joints.size(); ++j) {
    if (hasChild[j]) continue;
    const Eigen::Matrix4d& g = walk.global[joints[j]];
    const Eigen::Vector3d head = g.topRightCorner<3, 1>(), axis = g.block<3, 1>(0, 1).normalized();
    double reach = 0;
    for (int v : verticesOf[joints[j]->mName.C_Str()])
      reach = std::max(reach, (vertices[size_t(v)] - head).dot(axis));
    if (reach <= 1e-6 * size) continue;
    const int tail = nodeAt(head + reach * axis);
    edges.insert({std::min(nodeOf[j], tail), std::max(nodeOf[j], tail)});
    segmentOf[j] = {nodeOf[j], tail};
  }
  for (const auto& [a, b] : edges) s.edges.push_back({a, b});
  const auto root = std::find_if(joints.begin(), joints.end(), [&](const aiNode* j) {
    return !j->mParent || !jointIndex.count(j->mParent);
  });
  s.root = nodeOf[size_t(root - joints.begin())];

  // Radii from the weights' spread.
  if (verticesOf.empty()) return rig;
  std::vector<std::vector<double>> distances(s.nodes.size());
  for (size_t j = 0; j < joints.size(); ++j) {
    const auto [head, tail] = segmentOf[j];
    if (head < 0) continue;
    for (int v : verticesOf[joints[j]->mName.C_Str()])
      distances[size_t(head)].push_back(
          distanceToSegment(vertices[size_t(v)], s.nodes[size_t(head)], s.nodes[size_t(tail)]));
  }
  s.radii.assign(s.nodes.size(), 0.0);
  for (size_t n = 0; n < s.nodes.size(); ++n)
    if (!distances[n].empty()) {
      auto middle = distances[n].begin() + long(distances[n].size() / 2);
      std::nth_element(distances[n].begin(), middle, distances[n].end());
      s.radii[n] = *middle;
    }
  for (int pass = 0; pass < s.nodeCount(); ++pass) {  // nodes without vertices: their neighbours' mean
    bool changed = false;
    for (size_t n = 0; n < s.nodes.size(); ++n) {
      if (s.radii[n] > 0) continue;
      double sum = 0;
      int count = 0;
      for (const auto& e : s.edges)
        for (int end = 0; end < 2; ++end)
          if (size_t(e[size_t(end)]) == n && s.radii[size_t(e[size_t(1 - end)])] > 0) {
            sum += s.radii[size_t(e[size_t(1 - end)])];
            ++count;
          }
      if (count) {
        s.radii[n] = sum / count;
        changed = true;
      }
    }
    if (!changed) break;
  }
  const double fallback = 1e-3 * size;  // an isolated node without vertices
  for (double& r : s.radii)
    if (!(r > 0)) r = fallback;
  return rig;
}

}  // namespace medial
