#include "rig/RigImport.h"

#include "skeleton/SegmentDistance.h"

#include <assimp/Importer.hpp>
#include <assimp/ai_assert.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

// Debian's Assimp 5.2 is built with its assertions on, and a malformed FBX file trips some of them
// (fuzz_rig_import: FBXConverter's "out_idx != nullptr"): Assimp's aiAssertViolation prints and aborts the
// process, the GUI with it. This definition takes the place of the library's (the dynamic linker binds the
// library's calls to the first definition in its search order, and Medial's code comes before libassimp)
// and throws instead: Assimp's ReadFile catches the exception and reports the file as unreadable.
namespace Assimp {
void aiAssertViolation(const char* failedExpression, const char* file, int line) {
  throw std::runtime_error(std::string("the file breaks one of Assimp's checks (") + failedExpression + ")");
}
}  // namespace Assimp

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

// What the steps of importRig share: the scene, its nodes' global transforms, the merged mesh, the joints
// and where they went in the skeleton.
struct Import {
  const aiScene* scene = nullptr;
  Walk walk;
  std::set<std::string> jointNames;
  std::vector<std::pair<std::string, double>> strongest;  // per merged vertex: (joint, weight)
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
  std::vector<const aiNode*> joints;
  std::map<const aiNode*, int> jointIndex;
  std::vector<int> nodeOf;                             // joint -> skeleton node
  std::vector<std::pair<int, int>> segmentOf;          // joint -> (head node, tail node)
  std::map<std::string, std::vector<int>> verticesOf;  // joint name -> vertices it weighs most
  double size = 0;                                     // the mesh's bounding-box diagonal
};

// The meshes in scene space, merged; the joints and, per vertex, its largest weight's joint.
void mergeMeshes(const aiNode* node, Import& in) {
  const Eigen::Matrix4d& g = in.walk.global[node];
  // A malformed file can name meshes, vertices and faces that are not there (fuzz_rig_import): those are
  // left out.
  for (unsigned k = 0; k < node->mNumMeshes; ++k) {
    if (node->mMeshes[k] >= in.scene->mNumMeshes || !in.scene->mMeshes[node->mMeshes[k]]) continue;
    const aiMesh* mesh = in.scene->mMeshes[node->mMeshes[k]];
    const int first = int(in.vertices.size());
    const auto exists = [mesh](unsigned v) { return v < mesh->mNumVertices; };
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      in.vertices.push_back((g * Eigen::Vector4d(p.x, p.y, p.z, 1)).head<3>());
    }
    in.strongest.resize(in.vertices.size(), {std::string(), 0.0});
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
      if (mesh->mFaces[f].mNumIndices == 3 && exists(mesh->mFaces[f].mIndices[0]) &&
          exists(mesh->mFaces[f].mIndices[1]) && exists(mesh->mFaces[f].mIndices[2]))
        in.faces.emplace_back(first + int(mesh->mFaces[f].mIndices[0]),
                              first + int(mesh->mFaces[f].mIndices[1]),
                              first + int(mesh->mFaces[f].mIndices[2]));
    for (unsigned b = 0; b < mesh->mNumBones; ++b) {
      const aiBone* bone = mesh->mBones[b];
      in.jointNames.insert(bone->mName.C_Str());
      for (unsigned w = 0; w < bone->mNumWeights; ++w) {
        if (!exists(bone->mWeights[w].mVertexId)) continue;
        auto& s = in.strongest[size_t(first) + bone->mWeights[w].mVertexId];
        if (bone->mWeights[w].mWeight > s.second) s = {bone->mName.C_Str(), bone->mWeights[w].mWeight};
      }
    }
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) mergeMeshes(node->mChildren[c], in);
}

// Joints: the skin's bones and their ancestors below the first common one that is not a joint.
void findJoints(Import& in) {
  for (const auto& [node, global] : in.walk.global)
    if (in.jointNames.count(node->mName.C_Str())) in.jointIndex[node] = 0;
  for (auto it = in.jointIndex.begin(); it != in.jointIndex.end(); ++it) {
    // Medial's and Blender's root joints drive nothing: a parent of a joint whose name says so is one too.
    for (const aiNode* p = it->first->mParent; p && !in.jointIndex.count(p); p = p->mParent)
      if (std::string(p->mName.C_Str()) == "Root") in.jointIndex[p] = 0;
  }
  // Medial's end joints mark bone tails (buildSkeleton reads them); Root_end marks nothing.
  for (auto it = in.jointIndex.begin(); it != in.jointIndex.end();) {
    const std::string name = it->first->mName.C_Str();
    const bool end = name.size() > 4 && name.compare(name.size() - 4, 4, "_end") == 0;
    it = end && it->first->mNumChildren == 0 ? in.jointIndex.erase(it) : std::next(it);
  }
  for (auto& [node, index] : in.jointIndex) {
    index = int(in.joints.size());
    in.joints.push_back(node);
  }
}

// Where a joint sits; Medial's "Root" stands on the ground below the skeleton (rig/RigBones.h): its place
// in the skeleton is its first child joint's (Root_end, below it, is no joint: findJoints).
Eigen::Vector3d jointPosition(Import& in, const aiNode* joint) {
  if (std::string(joint->mName.C_Str()) == "Root")
    for (unsigned c = 0; c < joint->mNumChildren; ++c)
      if (in.jointIndex.count(joint->mChildren[c]))
        return in.walk.global[joint->mChildren[c]].topRightCorner<3, 1>();
  return in.walk.global[joint].topRightCorner<3, 1>();
}

// The child node "<joint>_end" (rig/RigBones.h's end joints), or null.
const aiNode* endJoint(const aiNode* joint) {
  const std::string name = std::string(joint->mName.C_Str()) + "_end";
  for (unsigned c = 0; c < joint->mNumChildren; ++c)
    if (name == joint->mChildren[c]->mName.C_Str()) return joint->mChildren[c];
  return nullptr;
}

// Nodes at the joints (the same place once), edges from each joint to its child joints, and for leaf
// bones their end joint or a tail along Y as far as their vertices reach; the root is the joint without a
// joint parent.
void buildSkeleton(Import& in, Skeleton& s) {
  in.nodeOf.resize(in.joints.size());
  auto nodeAt = [&](const Eigen::Vector3d& p) {
    for (int n = 0; n < s.nodeCount(); ++n)
      if ((s.nodes[size_t(n)] - p).norm() <= 1e-6 * in.size) return n;
    s.nodes.push_back(p);
    return s.nodeCount() - 1;
  };
  for (size_t j = 0; j < in.joints.size(); ++j) in.nodeOf[j] = nodeAt(jointPosition(in, in.joints[j]));
  std::set<std::pair<int, int>> edges;
  std::vector<bool> hasChild(in.joints.size(), false);
  in.segmentOf.assign(in.joints.size(), {-1, -1});
  for (size_t j = 0; j < in.joints.size(); ++j) {
    const aiNode* parent = in.joints[j]->mParent;
    if (parent && in.jointIndex.count(parent)) {
      const int p = in.jointIndex[parent];
      hasChild[size_t(p)] = true;
      if (in.nodeOf[size_t(p)] != in.nodeOf[j]) {
        edges.insert(
            {std::min(in.nodeOf[size_t(p)], in.nodeOf[j]), std::max(in.nodeOf[size_t(p)], in.nodeOf[j])});
        in.segmentOf[size_t(p)] = {in.nodeOf[size_t(p)], in.nodeOf[j]};
      }
    }
  }
  for (size_t v = 0; v < in.strongest.size(); ++v)
    if (!in.strongest[v].first.empty()) in.verticesOf[in.strongest[v].first].push_back(int(v));
  for (size_t j = 0; j < in.joints.size(); ++j) {
    if (hasChild[j]) continue;
    const Eigen::Matrix4d& g = in.walk.global[in.joints[j]];
    if (const aiNode* end = endJoint(in.joints[j])) {  // Medial's end joint marks the tail
      const int tail = nodeAt(in.walk.global[end].topRightCorner<3, 1>());
      if (tail != in.nodeOf[j]) {
        edges.insert({std::min(in.nodeOf[j], tail), std::max(in.nodeOf[j], tail)});
        in.segmentOf[j] = {in.nodeOf[j], tail};
        continue;
      }
    }
    const Eigen::Vector3d head = g.topRightCorner<3, 1>(), axis = g.block<3, 1>(0, 1).normalized();
    double reach = 0;
    for (int v : in.verticesOf[in.joints[j]->mName.C_Str()])
      reach = std::max(reach, (in.vertices[size_t(v)] - head).dot(axis));
    if (reach <= 1e-6 * in.size) continue;
    const int tail = nodeAt(head + reach * axis);
    edges.insert({std::min(in.nodeOf[j], tail), std::max(in.nodeOf[j], tail)});
    in.segmentOf[j] = {in.nodeOf[j], tail};
  }
  for (const auto& [a, b] : edges) s.edges.push_back({a, b});
  const auto root = std::find_if(in.joints.begin(), in.joints.end(), [&](const aiNode* j) {
    return !j->mParent || !in.jointIndex.count(j->mParent);
  });
  s.root = in.nodeOf[size_t(root - in.joints.begin())];
}

// Radii from the weights' spread: a node's median distance of the vertices its bone weighs most; nodes
// without vertices take their neighbours' mean.
void setRadii(Import& in, Skeleton& s) {
  std::vector<std::vector<double>> distances(s.nodes.size());
  for (size_t j = 0; j < in.joints.size(); ++j) {
    const auto [head, tail] = in.segmentOf[j];
    if (head < 0) continue;
    for (int v : in.verticesOf[in.joints[j]->mName.C_Str()])
      distances[size_t(head)].push_back(
          distanceToSegment(in.vertices[size_t(v)], s.nodes[size_t(head)], s.nodes[size_t(tail)]));
  }
  s.radii.assign(s.nodes.size(), 0.0);
  for (size_t n = 0; n < s.nodes.size(); ++n)
    if (!distances[n].empty()) {
      auto middle = distances[n].begin() + long(distances[n].size() / 2);
      std::nth_element(distances[n].begin(), middle, distances[n].end());
      s.radii[n] = *middle;
    }
  for (int pass = 0; pass < s.nodeCount(); ++pass) {
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
  const double fallback = 1e-3 * in.size;  // an isolated node without vertices
  for (double& r : s.radii)
    if (!(r > 0)) r = fallback;
}

}  // namespace

ImportedRig importRig(const std::string& path) {
  ImportedRig rig;
  Assimp::Importer importer;
  // Assimp's FBX importer gives each face corner a vertex of its own: joined again (weights follow).
  Import in;
  in.scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (!in.scene || !in.scene->mRootNode) {
    rig.error = importer.GetErrorString();
    if (rig.error.empty()) rig.error = "not a scene Assimp can read";
    return rig;
  }
  in.walk.visit(in.scene->mRootNode, Eigen::Matrix4d::Identity());
  mergeMeshes(in.scene->mRootNode, in);
  if (in.faces.empty()) {
    rig.error = "the file holds no triangles";
    return rig;
  }
  rig.mesh.vertices.resize(Eigen::Index(in.vertices.size()), 3);
  for (size_t v = 0; v < in.vertices.size(); ++v)
    rig.mesh.vertices.row(Eigen::Index(v)) = in.vertices[v].transpose();
  rig.mesh.faces.resize(Eigen::Index(in.faces.size()), 3);
  for (size_t f = 0; f < in.faces.size(); ++f) rig.mesh.faces.row(Eigen::Index(f)) = in.faces[f].transpose();

  findJoints(in);
  rig.joints = int(in.joints.size());
  if (in.joints.empty()) return rig;
  in.size = (rig.mesh.vertices.colwise().maxCoeff() - rig.mesh.vertices.colwise().minCoeff()).norm();
  buildSkeleton(in, rig.skeleton);
  if (in.verticesOf.empty()) return rig;
  setRadii(in, rig.skeleton);
  return rig;
}

}  // namespace medial
