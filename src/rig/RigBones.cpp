#include "rig/RigBones.h"

#include "common/Parallel.h"
#include "skeleton/SegmentDistance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>

namespace medial {

namespace {

// The ground under the root joint: at least this share of the mesh's height below its lowest point.
constexpr double kGroundGap = 0.05;

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

// An end joint at the tail of every bone no other bone continues: glTF and FBX store no tails, and an
// importer places a bone's tail at its child (Blender's glTF "Temperance" and FBX importers do).
void addEndJoints(std::vector<RigBone>& bones, const Skeleton& skeleton) {
  std::vector<bool> continued(bones.size(), false);
  for (const RigBone& bone : bones)
    if (bone.parent >= 0) continued[size_t(bone.parent)] = true;
  const size_t count = bones.size();
  for (size_t b = 1; b < count; ++b) {
    if (continued[b]) continue;
    RigBone end;
    end.name = bones[b].name + "_end";
    end.head = end.tail = bones[b].tail;
    end.parent = int(b);
    end.global = bones[b].global;
    end.global.topRightCorner<3, 1>() = skeleton.nodes[size_t(bones[b].tail)];
    bones.push_back(end);
  }
}

// The farthest any vertex lies from the skeleton (its distance to the nearest bone).
double farthestFromTheSkeleton(const Skeleton& skeleton, const Vertices& mesh) {
  std::vector<double> distance(size_t(mesh.rows()), 0.0);
  inParallel(distance.size(), [&](size_t v) {
    const Eigen::Vector3d p = mesh.row(Eigen::Index(v)).transpose();
    double nearest = INFINITY;
    for (const auto& e : skeleton.edges)
      nearest =
          std::min(nearest, distanceToSegment(p, skeleton.nodes[size_t(e[0])], skeleton.nodes[size_t(e[1])]));
    distance[v] = nearest;
  });
  return distance.empty() ? 0.0 : *std::max_element(distance.begin(), distance.end());
}

// The root joint on the ground below the root node, and "Root_end" below it, so that the bone an importer
// makes of Root lies outside the mesh: Blender's automatic weights then give it no vertex. Blender's bone
// heat weighs a vertex by its nearest bone, the distance divided by (1 + cos) / 2 of the angle between
// the vertex normal and the direction from the bone: a ground twice as far below the lowest vertex as
// any vertex lies from the skeleton keeps Root farther than every vertex's own bone wherever that angle is
// at most 90 degrees. The importers' bones: glTF's (Temperance) points at its children's centroid and is
// as long as the nearest child - Root_end, a quarter of the gap below, makes it that short; FBX's follows
// Root's Y axis, here down, away from the mesh.
void putRootOnTheGround(std::vector<RigBone>& bones, const Skeleton& skeleton, const Vertices& mesh) {
  if (mesh.rows() == 0) return;
  const double low = mesh.col(1).minCoeff(), high = mesh.col(1).maxCoeff();
  const double gap = std::max(kGroundGap * (high - low), 2 * farthestFromTheSkeleton(skeleton, mesh));
  RigBone& root = bones[0];
  const Eigen::Vector3d node = root.global.topRightCorner<3, 1>();
  const Eigen::Vector3d ground(node.x(), low - gap, node.z());
  Eigen::Matrix4d down = Eigen::Matrix4d::Identity();
  down.topLeftCorner<3, 3>() = Eigen::Vector3d(1, -1, -1).asDiagonal();  // half a turn about X
  root.global = down;
  root.global.topRightCorner<3, 1>() = ground;
  RigBone& end = bones.back();  // Root_end (addRootEnd)
  end.global = down;
  end.global.topRightCorner<3, 1>() = ground - Eigen::Vector3d::UnitY() * (gap / 4);
}

// "Root_end", where the root joint is (putRootOnTheGround moves both), so that the names are the same
// with or without the mesh.
void addRootEnd(std::vector<RigBone>& bones) {
  RigBone end = bones[0];
  end.name = "Root_end";
  end.parent = 0;
  bones.push_back(end);
}

}  // namespace

int rigRootNode(const Skeleton& skeleton) {
  return skeleton.root >= 0 && skeleton.root < skeleton.nodeCount() ? skeleton.root : 0;
}

std::vector<RigBone> buildRigBones(const Skeleton& skeleton, const Vertices* ground) {
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
  addEndJoints(bones, skeleton);
  addRootEnd(bones);
  if (ground) putRootOnTheGround(bones, skeleton, *ground);
  return bones;
}

namespace {

using Influences = std::vector<std::pair<int, double>>;  // (bone, weight) of one vertex, strongest first

// The vertex where bone `edge` weighs most, or, for a bone no heat reached, the vertex nearest its middle.
int strongestVertex(const Rig& rig, int edge) {
  Eigen::Index best = 0;
  if (rig.weights.col(edge).maxCoeff(&best) > 0) return int(best);
  const auto& e = rig.skeleton.edges[size_t(edge)];
  const Eigen::RowVector3d middle =
      ((rig.skeleton.nodes[size_t(e[0])] + rig.skeleton.nodes[size_t(e[1])]) / 2).transpose();
  (rig.mesh.vertices.rowwise() - middle).rowwise().squaredNorm().minCoeff(&best);
  return int(best);
}

// A bone that lost every vertex to the cap takes its strongest vertex (and the vertices where it weighs at
// least half as much) in place of each one's weakest kept influence, with its own weight - or, where no heat
// reached it, the weight of the influence it replaces.
void reviveDeadBones(const Rig& rig, size_t keep, std::vector<Influences>& perVertex) {
  std::vector<bool> alive(size_t(rig.weights.cols()), false);
  for (const Influences& kept : perVertex)
    for (const auto& [bone, weight] : kept) alive[size_t(bone)] = true;
  for (int edge = 0; edge < int(alive.size()); ++edge) {
    if (alive[size_t(edge)]) continue;
    const int strongest = strongestVertex(rig, edge);
    const double peak = rig.weights(strongest, edge);
    for (Eigen::Index v = 0; v < rig.weights.rows(); ++v) {
      if (v != strongest && !(peak > 0 && rig.weights(v, edge) >= peak / 2)) continue;
      Influences& kept = perVertex[size_t(v)];
      // The weakest influence of a bone that was alive (not one revived here before).
      auto weakest = kept.end();
      for (auto it = kept.begin(); it != kept.end(); ++it)
        if (alive[size_t(it->first)] && (weakest == kept.end() || it->second < weakest->second)) weakest = it;
      const double weight = peak > 0 ? rig.weights(v, edge) : weakest == kept.end() ? 1.0 : weakest->second;
      if (kept.size() < keep)
        kept.emplace_back(edge, weight);
      else if (weakest != kept.end())
        *weakest = {edge, weight};
    }
  }
}

}  // namespace

std::vector<std::vector<std::pair<int, double>>> keptInfluences(const Rig& rig, int maxInfluences) {
  const size_t bones = size_t(rig.weights.cols());
  const size_t keep = std::min(bones, size_t(std::max(1, maxInfluences)));
  std::vector<Influences> perVertex(size_t(rig.weights.rows()));
  std::vector<int> order(bones);
  for (Eigen::Index v = 0; v < rig.weights.rows(); ++v) {
    std::iota(order.begin(), order.end(), 0);
    std::partial_sort(order.begin(), order.begin() + long(keep), order.end(),
                      [&](int a, int b) { return rig.weights(v, a) > rig.weights(v, b); });
    for (size_t k = 0; k < keep; ++k)
      if (rig.weights(v, order[k]) > 0) perVertex[size_t(v)].emplace_back(order[k], rig.weights(v, order[k]));
  }
  if (rig.mesh.vertices.rows() == rig.weights.rows()) reviveDeadBones(rig, keep, perVertex);
  std::vector<std::vector<std::pair<int, double>>> perEdge(bones);
  for (size_t v = 0; v < perVertex.size(); ++v) {
    double sum = 0;
    for (const auto& [bone, weight] : perVertex[v]) sum += weight;
    if (!(sum > 0)) continue;
    for (const auto& [bone, weight] : perVertex[v]) perEdge[size_t(bone)].push_back({int(v), weight / sum});
  }
  return perEdge;
}

}  // namespace medial
