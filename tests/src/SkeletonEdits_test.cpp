// SkeletonEdits: the skeleton editor's edits keep a valid skeleton (radii, root) and refuse bad ids.
#include "skeleton/SkeletonEdits.h"

#include <gtest/gtest.h>

namespace {

// A T: 0 - 1 - 2 along x, and 1 - 3 up; radii 1, 2, 3, 4; root 0.
medial::Skeleton tee() {
  medial::Skeleton s;
  s.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
  s.radii = {1, 2, 3, 4};
  s.edges = {{0, 1}, {1, 2}, {1, 3}};
  s.root = 0;
  return s;
}

}  // namespace

TEST(SkeletonEdits, SplitAndBranchAddNodesWithRadii) {
  medial::Skeleton s = tee();
  const int middle = medial::splitEdge(s, 1, 0.25);
  ASSERT_EQ(middle, 4);
  EXPECT_TRUE(s.nodes[4].isApprox(Eigen::Vector3d(1.25, 0, 0)));
  EXPECT_DOUBLE_EQ(s.radii[4], 2.25);
  EXPECT_EQ(s.edgeCount(), 4);
  EXPECT_EQ(medial::nodeDegrees(s)[4], 2);
  const int leaf = medial::addBranch(s, 3, {1, 2, 0});
  ASSERT_EQ(leaf, 5);
  EXPECT_DOUBLE_EQ(s.radii[5], 4);
  EXPECT_EQ(medial::nodeDegrees(s)[3], 2);
  EXPECT_TRUE(medial::validateSkeleton(s).empty());
  EXPECT_EQ(medial::splitEdge(s, 99, 0.5), -1);
  EXPECT_EQ(medial::addBranch(s, -1, {0, 0, 0}), -1);
}

TEST(SkeletonEdits, DeletingAChainNodeBridgesItsNeighbours) {
  medial::Skeleton s = tee();
  medial::splitEdge(s, 1, 0.5);  // node 4 between 1 and 2
  ASSERT_TRUE(medial::deleteNode(s, 4));
  EXPECT_EQ(s.nodeCount(), 4);
  EXPECT_EQ(s.edgeCount(), 3);
  EXPECT_EQ(medial::nodeDegrees(s), (std::vector<int>{1, 3, 1, 1}));
  // A branch node goes with its edges; ids above it shift down, the root with them.
  ASSERT_TRUE(medial::setRoot(s, 3));
  ASSERT_TRUE(medial::deleteNode(s, 1));
  EXPECT_EQ(s.nodeCount(), 3);
  EXPECT_EQ(s.edgeCount(), 0);
  EXPECT_EQ(s.root, 2);
  EXPECT_EQ(s.radii, (std::vector<double>{1, 3, 4}));
  // The root deleted: a neighbour takes over.
  medial::Skeleton t = tee();
  ASSERT_TRUE(medial::deleteNode(t, 0));
  EXPECT_EQ(t.root, 0) << "node 1, now 0";
  EXPECT_TRUE(medial::validateSkeleton(t).empty());
  EXPECT_FALSE(medial::deleteNode(t, 7));
}

TEST(SkeletonEdits, RadiusAndMoveValidateTheirInput) {
  medial::Skeleton s = tee();
  EXPECT_TRUE(medial::setNodeRadius(s, 2, 0.5));
  EXPECT_DOUBLE_EQ(s.radii[2], 0.5);
  EXPECT_FALSE(medial::setNodeRadius(s, 2, 0));
  EXPECT_FALSE(medial::setNodeRadius(s, 2, NAN));
  EXPECT_TRUE(medial::moveNode(s, 3, {1, 3, 0}));
  EXPECT_FALSE(medial::moveNode(s, 4, {0, 0, 0}));
  medial::Skeleton bare = tee();
  bare.radii.clear();
  ASSERT_TRUE(medial::setNodeRadius(bare, 0, 0.2));
  ASSERT_EQ(bare.radii.size(), 4u);
  EXPECT_NEAR(bare.radii[1], 0.01 * std::sqrt(5.0), 1e-12);
}

TEST(SkeletonEdits, NearestEdgeToAViewRay) {
  const medial::Skeleton s = tee();
  // Looking down -z at (1.6, 0.05): edge 1 (1,0,0)-(2,0,0) at t = 0.6.
  const auto hit = medial::nearestEdgeToRay(s, {1.6, 0.05, 10}, {0, 0, -1});
  EXPECT_EQ(hit.edge, 1);
  EXPECT_NEAR(hit.t, 0.6, 1e-9);
  EXPECT_NEAR(hit.distance, 0.05, 1e-9);
  EXPECT_EQ(medial::nearestEdgeToRay(medial::Skeleton{}, {0, 0, 0}, {0, 0, 1}).edge, -1);
}
