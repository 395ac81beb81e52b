#include "sqm/SkeletonStraightening.h"

namespace medial {

std::vector<int> SqmTree::neighbours(int k) const {
  std::vector<int> result;
  if (parent[size_t(k)] >= 0) result.push_back(parent[size_t(k)]);
  result.insert(result.end(), children[size_t(k)].begin(), children[size_t(k)].end());
  return result;
}

SqmTree buildSqmTree(const Skeleton& skeleton, int start, int preferredRoot) {
  const int n = skeleton.nodeCount();
  std::vector<std::vector<int>> adjacent(static_cast<size_t>(n));
  for (const auto& e : skeleton.edges) {
    adjacent[size_t(e[0])].push_back(e[1]);
    adjacent[size_t(e[1])].push_back(e[0]);
  }
  // The component, and whether `preferredRoot` is in it.
  std::vector<bool> inComponent(static_cast<size_t>(n), false);
  std::vector<int> stack{start}, component;
  inComponent[size_t(start)] = true;
  while (!stack.empty()) {
    const int k = stack.back();
    stack.pop_back();
    component.push_back(k);
    for (int m : adjacent[size_t(k)])
      if (!inComponent[size_t(m)]) {
        inComponent[size_t(m)] = true;
        stack.push_back(m);
      }
  }
  int root =
      preferredRoot >= 0 && preferredRoot < n && inComponent[size_t(preferredRoot)] ? preferredRoot : start;

  SqmTree tree;
  tree.parent.assign(size_t(n), -1);
  tree.children.assign(size_t(n), {});
  // Extension 1: re-root at the first branch node met depth-first from the requested root. (Iterative
  // walks: a centerline skeleton can have tens of thousands of nodes in a row.)
  auto firstBranchFrom = [&](int from) {
    std::vector<bool> seen(static_cast<size_t>(n), false);
    std::vector<int> todo{from};
    seen[size_t(from)] = true;
    while (!todo.empty()) {
      const int k = todo.back();
      todo.pop_back();
      if (adjacent[size_t(k)].size() >= 3) return k;
      for (auto m = adjacent[size_t(k)].rbegin(); m != adjacent[size_t(k)].rend(); ++m)
        if (!seen[size_t(*m)]) {
          seen[size_t(*m)] = true;
          todo.push_back(*m);
        }
    }
    return -1;
  };
  if (adjacent[size_t(root)].size() < 3) {
    const int branch = firstBranchFrom(root);
    if (branch >= 0) {
      root = branch;
    } else {
      // Extension 2: a linear skeleton, rooted at an end (the requested root's end when it is one).
      for (int k : component)
        if (adjacent[size_t(k)].size() <= 1 && adjacent[size_t(root)].size() > 1) root = k;
    }
  }
  tree.root = root;
  // Depth-first preorder: every parent before its children.
  std::vector<int> todo{root};
  std::vector<bool> placed(static_cast<size_t>(n), false);
  placed[size_t(root)] = true;
  while (!todo.empty()) {
    const int k = todo.back();
    todo.pop_back();
    tree.nodes.push_back(k);
    if (adjacent[size_t(k)].size() >= 3) tree.hasBranchNode = true;
    for (int m : adjacent[size_t(k)])
      if (!placed[size_t(m)]) {
        placed[size_t(m)] = true;
        tree.parent[size_t(m)] = k;
        tree.children[size_t(k)].push_back(m);
      }
    for (auto c = tree.children[size_t(k)].rbegin(); c != tree.children[size_t(k)].rend(); ++c)
      todo.push_back(*c);
  }
  return tree;
}

BindPose straightenSkeleton(const Skeleton& skeleton, const SqmTree& tree) {
  BindPose pose;
  pose.position = skeleton.nodes;
  pose.rotation.assign(skeleton.nodes.size(), Eigen::Quaterniond::Identity());
  for (int k : tree.nodes) {  // depth-first: a parent is placed before its children
    const int parent = tree.parent[size_t(k)];
    for (int child : tree.children[size_t(k)]) {
      const Eigen::Vector3d offset =
          pose.rotation[size_t(k)] * (skeleton.nodes[size_t(child)] - skeleton.nodes[size_t(k)]);
      if (parent < 0 || tree.isBranch(k)) {
        // Children of a branch node (or of the root) keep their directions relative to it.
        pose.rotation[size_t(child)] = pose.rotation[size_t(k)];
        pose.position[size_t(child)] = pose.position[size_t(k)] + offset;
      } else {
        // The child of a connection node continues the line parent -> k.
        const Eigen::Vector3d direction =
            (pose.position[size_t(k)] - pose.position[size_t(parent)]).normalized();
        pose.rotation[size_t(child)] =
            (Eigen::Quaterniond::FromTwoVectors(offset, direction) * pose.rotation[size_t(k)]).normalized();
        pose.position[size_t(child)] = pose.position[size_t(k)] + offset.norm() * direction;
      }
    }
  }
  return pose;
}

}  // namespace medial
