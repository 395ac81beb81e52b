#include "rig/RigBones.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <deque>
#include <numeric>

namespace medial {

namespace {

// The frame at `head` with Y along head -> tail.
Eigen::Matrix4d boneFrame(const Eigen::Vector3d& head, const Eigen::Vector3d& tail) {
  Eigen::Vector3d direction = tail - head;
  if (direction.squaredNorm() == 0) direction = Eigen::Vector3d::UnitY();
  Eigen::Matrix4d frame = Eigen::Matrix4d::Identity();
  frame.topLeftCorner<3, 3>() =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitY(), direction.normalized()).toRotationMatrix();
  frame.topRightCorner<3, 1>() = head;
  return frame;
}

}  // namespace

int rigRootNode(const Skeleton& skeleton) {
  return skeleton.root >= 0 && skeleton.root < skeleton.nodeCount() ? skeleton.root : 0;
}

std::vector<RigBone> buildRigBones(const Skeleton& skeleton) {
  const int n = skeleton.nodeCount();
  std::vector<RigBone> bones;
  if (n == 0) return bones;
  const int root = rigRootNode(skeleton);
  RigBone rootJoint;
  rootJoint.name = "Root";
  rootJoint.head = rootJoint.tail = root;
  rootJoint.global.topRightCorner<3, 1>() = skeleton.nodes[size_t(root)];
  bones.push_back(rootJoint);

  std::vector<std::vector<std::pair<int, int>>> adjacent(static_cast<size_t>(n));  // (neighbour, edge)
  for (int e = 0; e < skeleton.edgeCount(); ++e) {
    adjacent[size_t(skeleton.edges[size_t(e)][0])].push_back({skeleton.edges[size_t(e)][1], e});
    adjacent[size_t(skeleton.edges[size_t(e)][1])].push_back({skeleton.edges[size_t(e)][0], e});
  }
  std::vector<bool> reached(static_cast<size_t>(n), false), edgeDone(size_t(skeleton.edgeCount()), false);
  std::vector<int> incomingBone(static_cast<size_t>(n), 0);  // the bone ending at a node; 0: the root joint
  std::vector<int> starts{root};
  for (int v = 0; v < n; ++v) starts.push_back(v);
  for (int start : starts) {
    if (reached[size_t(start)]) continue;
    reached[size_t(start)] = true;
    std::deque<int> queue{start};
    while (!queue.empty()) {
      const int u = queue.front();
      queue.pop_front();
      for (const auto& [v, e] : adjacent[size_t(u)]) {
        if (edgeDone[size_t(e)]) continue;
        edgeDone[size_t(e)] = true;
        RigBone bone;
        bone.name = "Bone_" + std::to_string(e) + "_" + std::to_string(u) + "_" + std::to_string(v);
        bone.edge = e;
        bone.head = u;
        bone.tail = v;
        bone.parent = incomingBone[size_t(u)];
        bone.global = boneFrame(skeleton.nodes[size_t(u)], skeleton.nodes[size_t(v)]);
        bones.push_back(bone);
        if (!reached[size_t(v)]) {  // a tree edge; otherwise it closes a cycle and v keeps its parent bone
          reached[size_t(v)] = true;
          incomingBone[size_t(v)] = int(bones.size()) - 1;
          queue.push_back(v);
        }
      }
    }
  }
  return bones;
}

std::vector<std::vector<std::pair<int, double>>> keptInfluences(const Rig& rig, int maxInfluences) {
  std::vector<std::vector<std::pair<int, double>>> perEdge(size_t(rig.weights.cols()));
  std::vector<int> order(size_t(rig.weights.cols()));
  const size_t keep = std::min(order.size(), size_t(std::max(1, maxInfluences)));
  for (Eigen::Index v = 0; v < rig.weights.rows(); ++v) {
    std::iota(order.begin(), order.end(), 0);
    std::partial_sort(order.begin(), order.begin() + long(keep), order.end(),
                      [&](int a, int b) { return rig.weights(v, a) > rig.weights(v, b); });
    double sum = 0;
    for (size_t k = 0; k < keep; ++k) sum += rig.weights(v, order[k]);
    if (!(sum > 0)) continue;
    for (size_t k = 0; k < keep; ++k)
      if (rig.weights(v, order[k]) > 0)
        perEdge[size_t(order[k])].push_back({int(v), rig.weights(v, order[k]) / sum});
  }
  return perEdge;
}

}  // namespace medial
