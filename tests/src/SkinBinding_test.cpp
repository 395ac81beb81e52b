// SkinBinding: heat weights for any mesh and skeleton, and the root a skeleton without one gets.
#include "ContractionTestMeshes.h"
#include "rig/SkinBinding.h"

#include <gtest/gtest.h>

using medial::testing::tubeMesh;

namespace {

medial::Skeleton pathOf(const std::vector<double>& xs) {
  medial::Skeleton s;
  for (double x : xs) s.nodes.emplace_back(x, 0, 0);
  for (int i = 0; i + 1 < int(xs.size()); ++i) s.edges.push_back({i, i + 1});
  return s;
}

}  // namespace

TEST(SkinBinding, CentralNodeIsTheMiddleOfTheLongestPath) {
  // Unevenly spaced: the middle by length (x = 5 of 0..10) is node 3, not the middle index 2.
  EXPECT_EQ(medial::centralNode(pathOf({0, 1, 2, 5, 10})), 3);
  // A figure: spine 0-1-2 (pelvis 0, chest 2), legs from 0, arms and head from 2. The longest path runs
  // foot to hand; its middle is on the spine, not at a limb's end.
  medial::Skeleton figure;
  figure.nodes = {{0, 0, 0},    {0, 0, 1},  {0, 0, 2}, {-0.5, 0, -2},
                  {0.5, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {0, 0, 2.5}};
  figure.edges = {{0, 1}, {1, 2}, {0, 3}, {0, 4}, {2, 5}, {2, 6}, {2, 7}};
  const int centre = medial::centralNode(figure);
  EXPECT_TRUE(centre == 0 || centre == 1 || centre == 2) << centre;
  // The longest component decides: a long bar (nodes 3-5) beside a short one (nodes 0-2).
  medial::Skeleton two = pathOf({0, 0.1, 0.2});
  for (double x : {10.0, 15.0, 20.0}) two.nodes.emplace_back(x, 0, 0);
  two.edges.push_back({3, 4});
  two.edges.push_back({4, 5});
  EXPECT_EQ(medial::centralNode(two), 4);
  EXPECT_EQ(medial::centralNode(medial::Skeleton{}), -1);
}

TEST(SkinBinding, TubeBoundToItsAxisHasWeightsSummingToOneAndTheCentralRoot) {
  const medial::TriangleMesh tube = tubeMesh(10, 1);  // x in [-5, 5]
  const medial::Skeleton axis = pathOf({-4.5, -1.5, 1.5, 4.5});
  const medial::SkinBindingResult r = medial::bindSkin(tube, axis);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.weights.rows(), tube.vertices.rows());
  ASSERT_EQ(r.weights.cols(), 3);
  EXPECT_EQ(r.nodesOutside, 0);
  EXPECT_TRUE(r.root == 1 || r.root == 2) << r.root;
  for (Eigen::Index j = 0; j < tube.vertices.rows(); ++j) {
    EXPECT_NEAR(r.weights.row(j).sum(), 1.0, 1e-9);
    const double x = tube.vertices(j, 0);
    if (x < -4) EXPECT_GT(r.weights(j, 0), 0.9) << x;
    if (x > 4) EXPECT_GT(r.weights(j, 2), 0.9) << x;
  }
  // A skeleton that names its root keeps it.
  medial::Skeleton rooted = axis;
  rooted.root = 0;
  EXPECT_EQ(medial::bindSkin(tube, rooted).root, 0);
}

TEST(SkinBinding, NodesOutsideAreCountedAndBadPairsAreErrors) {
  const medial::TriangleMesh tube = tubeMesh(10, 1);
  // The axis runs on past the tube's end (its cap reaches x = 6): 2 of its 5 nodes are outside, and it still
  // binds.
  const medial::SkinBindingResult longer = medial::bindSkin(tube, pathOf({-4, -2, 2, 6.5, 7}));
  ASSERT_TRUE(longer.ok()) << longer.error;
  EXPECT_EQ(longer.nodesOutside, 2);
  EXPECT_NEAR(longer.weights.row(0).sum(), 1.0, 1e-9);

  medial::Skeleton far = pathOf({100, 101});
  EXPECT_NE(medial::bindSkin(tube, far).error.message().find("outside the mesh's bounding box"),
            std::string::npos);
  EXPECT_NE(medial::bindSkin(tube, pathOf({0})).error.message().find("no edges"), std::string::npos);
  EXPECT_NE(medial::bindSkin(medial::TriangleMesh{}, pathOf({0, 1})).error.message().find("no faces"),
            std::string::npos);
}
