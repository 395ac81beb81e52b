// SkeletonRefinement and PartConnection of the sketch skeletonization (Ma et al. 2021, §3.2-3.3) on small
// hand-made graphs whose answer is known.
#include "sketch/PartConnection.h"
#include "sketch/SkeletonRefinement.h"

#include <gtest/gtest.h>

namespace {

// A horizontal bone 0-1-2 (part 0) with two spurs: at x = 10 a long one up (to y = 40) and at x = 12 a
// short one down (to y = -3). Nodes 1 and 3 are junctions 2 apart along the bones.
medial::SketchGraph twoJunctions() {
  medial::SketchGraph g;
  g.addNode({0, 0, 0}, 2, 0);    // 0 terminal
  g.addNode({10, 0, 0}, 2, 0);   // 1 junction
  g.addNode({30, 0, 0}, 2, 0);   // 2 terminal
  g.addNode({12, 0, 0}, 2, 0);   // 3 junction
  g.addNode({10, 40, 0}, 2, 0);  // 4 terminal of the long spur
  g.addNode({12, -3, 0}, 2, 0);  // 5 terminal of the short spur
  g.addEdge(0, 1, 0, 0);
  g.addEdge(1, 3, 0, 0);
  g.addEdge(3, 2, 0, 0);
  g.addEdge(1, 4, 0, 1);
  g.addEdge(3, 5, 0, 2);
  return g;
}

std::vector<double> everywhere(const medial::SketchGraph& g, double threshold) {
  return std::vector<double>(size_t(g.skeleton.nodeCount()), threshold);
}

}  // namespace

TEST(SkeletonRefinement, NearbyJunctionsMergeAtTheirCentroid) {
  medial::SketchGraph g = twoJunctions();
  EXPECT_EQ(medial::mergeJunctions(g, everywhere(g, 1)), 0) << "2 apart: a threshold of 1 keeps both";
  EXPECT_EQ(medial::mergeJunctions(g, everywhere(g, 5)), 1);
  EXPECT_EQ(g.skeleton.nodeCount(), 5);
  EXPECT_EQ(g.skeleton.edgeCount(), 4);
  bool merged = false;
  for (const auto& p : g.skeleton.nodes) merged |= (p - Eigen::Vector3d(11, 0, 0)).norm() < 1e-12;
  EXPECT_TRUE(merged) << "one junction at (11, 0, 0)";
}

TEST(SkeletonRefinement, ShortJunctionTerminalBranchesArePruned) {
  medial::SketchGraph g = twoJunctions();
  // The short spur reaches 3 + 2 - 2 = 3 beyond its junction's ball, the long one 40.
  EXPECT_EQ(medial::pruneBranches(g, everywhere(g, 2)), 0);
  EXPECT_EQ(medial::pruneBranches(g, everywhere(g, 10)), 1);
  EXPECT_EQ(g.skeleton.nodeCount(), 5);
  for (const auto& p : g.skeleton.nodes) EXPECT_GE(p.y(), 0) << "the short spur went, the long one stayed";
}

TEST(SkeletonRefinement, ShortInternalBonesCollapse) {
  medial::SketchGraph g = twoJunctions();
  EXPECT_EQ(medial::collapseEdges(g, everywhere(g, 1)), 0);
  EXPECT_EQ(medial::collapseEdges(g, everywhere(g, 5)), 1) << "the 2-long bone between the junctions";
  EXPECT_EQ(g.skeleton.nodeCount(), 5);
  EXPECT_EQ(g.skeleton.edgeCount(), 4);
  // Terminal bones stay whatever the threshold.
  medial::SketchGraph line;
  line.addNode({0, 0, 0}, 1, 0);
  line.addNode({1, 0, 0}, 1, 0);
  line.addEdge(0, 1, 0, 0);
  EXPECT_EQ(medial::collapseEdges(line, everywhere(line, 100)), 0);
}

TEST(PartConnection, AnOverlappingPartIsAttachedByABoneSplit) {
  medial::SketchGraph g;
  // Part 0: a bone from (0, 0) to (20, 0) of radius 3. Part 1: a bone whose end (10, 2) lies inside it.
  g.addNode({0, 0, 0}, 3, 0);
  g.addNode({20, 0, 0}, 3, 0);
  g.addEdge(0, 1, 0, 0);
  g.addNode({10, 2, 0}, 1, 1);
  g.addNode({10, 12, 0}, 1, 1);
  g.addEdge(2, 3, 1, 0);
  const auto attachments = medial::connectParts(g, 2);
  ASSERT_EQ(attachments.size(), 2u);
  EXPECT_EQ(attachments[0].parent, -1);
  EXPECT_EQ(attachments[1].parent, 0);
  EXPECT_TRUE(attachments[1].boneSplit);
  EXPECT_EQ(attachments[1].childJoint, 2);
  EXPECT_NEAR(attachments[1].distance, 2.0, 1e-12);
  // The split made a joint at the foot (10, 0), joined to the child's joint: one tree of 5 nodes.
  EXPECT_NEAR((g.skeleton.nodes[size_t(attachments[1].parentJoint)] - Eigen::Vector3d(10, 0, 0)).norm(), 0,
              1e-12);
  EXPECT_EQ(g.skeleton.nodeCount(), 5);
  EXPECT_EQ(g.skeleton.edgeCount(), 4);
}

TEST(PartConnection, APartOutsideEveryOtherIsARoot) {
  medial::SketchGraph g;
  g.addNode({0, 0, 0}, 1, 0);
  g.addNode({5, 0, 0}, 1, 0);
  g.addEdge(0, 1, 0, 0);
  g.addNode({0, 50, 0}, 1, 1);
  g.addNode({5, 50, 0}, 1, 1);
  g.addEdge(2, 3, 1, 0);
  const auto attachments = medial::connectParts(g, 2);
  EXPECT_EQ(attachments[1].parent, -1);
  EXPECT_EQ(g.skeleton.edgeCount(), 2);
}
