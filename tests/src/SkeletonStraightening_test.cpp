// SkeletonStraightening: the rooted tree SQM works on (re-rooting, extension 1 and 2) and the straightened
// bind pose (CESCG 2014 §4).
#include "sqm/SkeletonStraightening.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// A Y: branch node 0, arms 0-1-2, 0-3-4, 0-5-6, the first arm bent at node 1.
medial::Skeleton bentY() {
  medial::Skeleton s;
  s.nodes = {{0, 0, 0}, {1, 0, 0}, {1.6, 0.8, 0}, {-0.5, 1, 0}, {-1, 2, 0}, {-0.5, -1, 0}, {-1, -2, 0}};
  s.radii.assign(s.nodes.size(), 0.2);
  s.edges = {{0, 1}, {1, 2}, {0, 3}, {3, 4}, {0, 5}, {5, 6}};
  return s;
}

}  // namespace

TEST(SkeletonStraightening, TreeFromALeafIsRootedAtTheFirstBranchNode) {
  const medial::Skeleton s = bentY();
  const medial::SqmTree tree = medial::buildSqmTree(s, 2, 2);  // asked for leaf 2
  EXPECT_EQ(tree.root, 0);
  EXPECT_TRUE(tree.hasBranchNode);
  EXPECT_EQ(tree.nodes.size(), s.nodes.size());
  EXPECT_EQ(tree.parent[0], -1);
  EXPECT_EQ(tree.parent[2], 1);
  EXPECT_EQ(tree.parent[1], 0);
  EXPECT_TRUE(tree.isBranch(0));
  EXPECT_TRUE(tree.isLeaf(6));
  EXPECT_EQ(tree.neighbours(1), (std::vector<int>{0, 2}));
}

TEST(SkeletonStraightening, LinearSkeletonIsRootedAtAnEnd) {
  medial::Skeleton s;
  s.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 1, 0}};
  s.radii.assign(4, 0.2);
  s.edges = {{1, 2}, {0, 1}, {2, 3}};
  const medial::SqmTree tree = medial::buildSqmTree(s, 1, 1);
  EXPECT_FALSE(tree.hasBranchNode);
  EXPECT_TRUE(tree.root == 0 || tree.root == 3) << tree.root;
  EXPECT_EQ(tree.nodes.size(), 4u);
}

TEST(SkeletonStraightening, BentArmBecomesStraightAndKeepsItsLengths) {
  const medial::Skeleton s = bentY();
  const medial::SqmTree tree = medial::buildSqmTree(s, 0, 0);
  const medial::BindPose pose = medial::straightenSkeleton(s, tree);
  ASSERT_EQ(pose.position.size(), s.nodes.size());
  // Every edge keeps its length.
  for (const auto& e : s.edges)
    EXPECT_NEAR((pose.position[size_t(e[0])] - pose.position[size_t(e[1])]).norm(),
                (s.nodes[size_t(e[0])] - s.nodes[size_t(e[1])]).norm(), 1e-12);
  // The bent arm 0-1-2 is straight: node 2 on the line from 0 through 1.
  const Eigen::Vector3d d1 = (pose.position[1] - pose.position[0]).normalized();
  const Eigen::Vector3d d2 = (pose.position[2] - pose.position[1]).normalized();
  EXPECT_NEAR(d1.dot(d2), 1.0, 1e-12);
  // The branch node's arms keep their directions, and the rotations map input offsets to bind offsets.
  EXPECT_NEAR((pose.position[3] - pose.position[0]).normalized().dot((s.nodes[3] - s.nodes[0]).normalized()),
              1.0, 1e-12);
  for (int k : {1, 2, 3, 4}) {
    const int p = tree.parent[size_t(k)];
    const Eigen::Vector3d mapped = pose.rotation[size_t(k)] * (s.nodes[size_t(k)] - s.nodes[size_t(p)]);
    EXPECT_LT((mapped - (pose.position[size_t(k)] - pose.position[size_t(p)])).norm(), 1e-12) << k;
  }
}
