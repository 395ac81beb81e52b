#include "sketch/PartConnection.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace medial {

double boneDistance(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& joint,
                    double& t) {
  const Eigen::Vector3d ab = b - a;
  if (ab.dot(joint - a) >= 0 && (a - b).dot(joint - b) >= 0 && ab.squaredNorm() > 0) {
    t = ab.dot(joint - a) / ab.squaredNorm();
    return ab.cross(joint - a).norm() / ab.norm();  // |v_i v_j| sin(theta) scaled: distance to the line
  }
  const double da = (joint - a).norm(), db = (joint - b).norm();
  t = da <= db ? -1 : 2;
  return std::min(da, db);
}

bool insideCylinderBall(const SketchGraph& graph, int part, const Eigen::Vector3d& point) {
  const Skeleton& s = graph.skeleton;
  for (int v = 0; v < s.nodeCount(); ++v)
    if (graph.nodePart[v] == part && (s.nodes[v] - point).norm() <= s.radii[v]) return true;
  for (int e = 0; e < s.edgeCount(); ++e) {
    const int a = s.edges[e][0], b = s.edges[e][1];
    if (graph.nodePart[a] != part || graph.nodePart[b] != part) continue;
    double t;
    const double d = boneDistance(s.nodes[a], s.nodes[b], point, t);
    if (t >= 0 && t <= 1 && d <= (1 - t) * s.radii[a] + t * s.radii[b]) return true;
  }
  return false;
}

std::vector<PartAttachment> connectParts(SketchGraph& graph, int partCount) {
  std::vector<PartAttachment> attachments(partCount);
  for (int child = 1; child < partCount; ++child) {
    const auto neighbours = graph.adjacency();
    std::vector<int> candidates;  // terminal, junction and lone joints of the child
    for (int v = 0; v < graph.skeleton.nodeCount(); ++v)
      if (graph.nodePart[v] == child && neighbours[v].size() != 2) candidates.push_back(v);
    struct Best {
      double distance = std::numeric_limits<double>::infinity();
      int parent = -1, joint = -1, edge = -1, node = -1;
      double t = 0;
    } best;
    for (int parent = 0; parent < child; ++parent) {
      bool intersects = false;
      for (int c : candidates)
        intersects = intersects || insideCylinderBall(graph, parent, graph.skeleton.nodes[c]);
      if (!intersects) continue;
      for (int c : candidates) {
        const Eigen::Vector3d& p = graph.skeleton.nodes[c];
        bool parentHasBones = false;
        for (int e = 0; e < graph.skeleton.edgeCount(); ++e) {
          const int a = graph.skeleton.edges[e][0], b = graph.skeleton.edges[e][1];
          if (graph.nodePart[a] != parent || graph.nodePart[b] != parent) continue;
          parentHasBones = true;
          double t;
          const double d = boneDistance(graph.skeleton.nodes[a], graph.skeleton.nodes[b], p, t);
          if (d < best.distance) best = {d, parent, c, e, t < 0 ? a : t > 1 ? b : -1, t};
        }
        if (parentHasBones) continue;
        for (int v = 0; v < graph.skeleton.nodeCount(); ++v) {  // a parent made of one lone joint
          if (graph.nodePart[v] != parent) continue;
          const double d = (graph.skeleton.nodes[v] - p).norm();
          if (d < best.distance) best = {d, parent, c, -1, v, -1};
        }
      }
    }
    if (best.parent < 0) continue;  // a root
    PartAttachment& attachment = attachments[child];
    attachment.parent = best.parent;
    attachment.childJoint = best.joint;
    attachment.distance = best.distance;
    if (best.node < 0 && (best.t < 1e-6 || best.t > 1 - 1e-6)) {  // the foot is on an end joint
      best.node = graph.skeleton.edges[best.edge][best.t < 0.5 ? 0 : 1];
    }
    if (best.node >= 0) {
      attachment.parentJoint = best.node;  // joint connect event
    } else {
      // Bone split event: a new joint at the foot, the bone split in two.
      const auto [a, b] = graph.skeleton.edges[best.edge];
      const double t = best.t;
      const Eigen::Vector3d foot = (1 - t) * graph.skeleton.nodes[a] + t * graph.skeleton.nodes[b];
      const double radius = (1 - t) * graph.skeleton.radii[a] + t * graph.skeleton.radii[b];
      const int split = graph.addNode(foot, radius, best.parent);
      graph.skeleton.edges[best.edge] = {a, split};
      graph.addEdge(split, b, graph.edgePart[best.edge], graph.edgeBranch[best.edge]);
      attachment.parentJoint = split;
      attachment.boneSplit = true;
    }
    graph.addEdge(attachment.parentJoint, attachment.childJoint, child, -1);
  }
  return attachments;
}

}  // namespace medial
