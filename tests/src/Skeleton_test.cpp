#include "skeleton/Skeleton.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using medial::NodeType;
using medial::Skeleton;
using Kind = medial::SkeletonProblem::Kind;

namespace {

// A Y: node 0 is the branch, 1..3 leaves.
Skeleton makeY() {
  Skeleton s;
  s.nodes = {{0, 0, 0}, {1, 0, 0}, {-1, 1, 0}, {-1, -1, 0}};
  s.radii = {0.5, 0.2, 0.2, 0.2};
  s.edges = {{0, 1}, {0, 2}, {0, 3}};
  s.root = 0;
  return s;
}

bool hasProblem(const Skeleton& s, Kind kind) {
  for (const auto& p : medial::validateSkeleton(s))
    if (p.kind == kind) return true;
  return false;
}

}  // namespace

TEST(Skeleton, ValidSkeletonHasNoProblems) { EXPECT_TRUE(medial::validateSkeleton(makeY()).empty()); }

TEST(Skeleton, NaNCoordinateIsReported) {
  Skeleton s = makeY();
  s.nodes[2].y() = std::numeric_limits<double>::quiet_NaN();
  const auto problems = medial::validateSkeleton(s);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].kind, Kind::NonFiniteCoordinate);
  EXPECT_EQ(problems[0].index, 2);
  EXPECT_NE(problems[0].message.find("node 2"), std::string::npos) << problems[0].message;
}

TEST(Skeleton, InfiniteCoordinateIsReported) {
  Skeleton s = makeY();
  s.nodes[1].x() = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(hasProblem(s, Kind::NonFiniteCoordinate));
}

TEST(Skeleton, ZeroAndNegativeRadiiAreReported) {
  Skeleton s = makeY();
  s.radii[1] = 0.0;
  s.radii[3] = -1.0;
  const auto problems = medial::validateSkeleton(s);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].kind, Kind::NonPositiveRadius);
  EXPECT_EQ(problems[0].index, 1);
  EXPECT_EQ(problems[1].index, 3);
}

TEST(Skeleton, NaNRadiusIsReported) {
  Skeleton s = makeY();
  s.radii[0] = std::nan("");
  EXPECT_TRUE(hasProblem(s, Kind::NonPositiveRadius));
}

TEST(Skeleton, RadiusCountMismatchIsReported) {
  Skeleton s = makeY();
  s.radii.pop_back();
  EXPECT_TRUE(hasProblem(s, Kind::RadiusCountMismatch));
}

TEST(Skeleton, MissingRadiiAreAllowed) {
  Skeleton s = makeY();
  s.radii.clear();
  EXPECT_TRUE(medial::validateSkeleton(s).empty());
}

TEST(Skeleton, SelfLoopEdgeIsReported) {
  Skeleton s = makeY();
  s.edges.push_back({2, 2});
  const auto problems = medial::validateSkeleton(s);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].kind, Kind::SelfLoopEdge);
  EXPECT_EQ(problems[0].index, 3);
}

TEST(Skeleton, EdgeIdOutOfRangeIsReported) {
  Skeleton s = makeY();
  s.edges.push_back({1, 4});
  s.edges.push_back({-1, 0});
  const auto problems = medial::validateSkeleton(s);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].kind, Kind::EdgeIdOutOfRange);
  EXPECT_EQ(problems[1].kind, Kind::EdgeIdOutOfRange);
}

TEST(Skeleton, RootOutOfRangeIsReported) {
  Skeleton s = makeY();
  s.root = 7;
  EXPECT_TRUE(hasProblem(s, Kind::RootOutOfRange));
}

TEST(Skeleton, EllipsoidChecks) {
  Skeleton s = makeY();
  s.ellipsoidAxes.assign(3, Eigen::Matrix3d::Identity());
  EXPECT_TRUE(hasProblem(s, Kind::EllipsoidCountMismatch));
  s.ellipsoidAxes.assign(4, Eigen::Matrix3d::Identity());
  EXPECT_TRUE(medial::validateSkeleton(s).empty());
  s.ellipsoidAxes[1](0, 2) = std::nan("");
  EXPECT_TRUE(hasProblem(s, Kind::NonFiniteEllipsoid));
}

TEST(Skeleton, ProblemListIsBounded) {
  Skeleton s;
  for (int i = 0; i < 100; ++i) {
    s.nodes.emplace_back(std::nan(""), 0, 0);
    s.radii.push_back(1.0);
  }
  EXPECT_EQ(medial::validateSkeleton(s, 5).size(), 5u);
}

TEST(Skeleton, NodeTypesFollowDegree) {
  Skeleton s = makeY();
  s.nodes.emplace_back(2, 0, 0);
  s.radii.push_back(0.1);
  s.edges.push_back({1, 4});  // 1 becomes a connection node, 4 a leaf
  const auto types = medial::classifyNodes(s);
  EXPECT_EQ(types[0], NodeType::Branch);
  EXPECT_EQ(types[1], NodeType::Connection);
  EXPECT_EQ(types[2], NodeType::Leaf);
  EXPECT_EQ(types[4], NodeType::Leaf);
  EXPECT_EQ(medial::nodeDegrees(s)[0], 3);
}
