// HeatWeights: Baran-Popović heat diffusion (contraction paper III.E) on meshes with known skeletons.
#include "ContractionTestMeshes.h"
#include "rig/HeatWeights.h"
#include "contraction/SkeletonByContraction.h"

#include <gtest/gtest.h>

using medial::testing::appendMesh;
using medial::testing::torusMesh;
using medial::testing::tubeMesh;

namespace {

// Two bones along the axis of tubeMesh(10, 1): x in [-5, 0] and [0, 5].
medial::Skeleton twoBoneAxis() {
  medial::Skeleton s;
  s.nodes = {{-5, 0, 0}, {0, 0, 0}, {5, 0, 0}};
  s.edges = {{0, 1}, {1, 2}};
  return s;
}

}  // namespace

TEST(HeatWeights, TubeWithTwoBonesBlendsAtTheJoint) {
  const medial::TriangleMesh tube = tubeMesh(10, 1);
  const medial::InsideTest inside(tube);
  const auto r = medial::heatWeights(tube, twoBoneAxis(), inside);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.weights.rows(), tube.vertices.rows());
  ASSERT_EQ(r.weights.cols(), 2);
  EXPECT_EQ(r.invisibleVertices, 0);
  for (Eigen::Index j = 0; j < tube.vertices.rows(); ++j) {
    EXPECT_NEAR(r.weights.row(j).sum(), 1.0, 1e-12);
    EXPECT_GE(r.weights.row(j).minCoeff(), 0.0);
    const double x = tube.vertices(j, 0);
    // Far from the joint a vertex follows its own bone (the blend decays over about a tube radius, 1,
    // for c = 1); at the joint both bones share it, and bone 0's weight falls monotonically along the
    // tube (checked ring by ring below).
    if (x < -4) {
      EXPECT_GT(r.weights(j, 0), 0.97) << x;
    }
    if (x > 4) {
      EXPECT_GT(r.weights(j, 1), 0.97) << x;
    }
    if (std::abs(x) > 2) {
      EXPECT_GT(r.weights(j, x < 0 ? 0 : 1), 0.85) << x;
    }
    if (std::abs(x) < 0.2) {
      EXPECT_NEAR(r.weights(j, 0), 0.5, 0.15) << x;
    }
  }
  const int sides = 16;
  for (int ring = 1; ring < 40; ++ring)
    EXPECT_LE(r.weights(ring * sides, 0), r.weights((ring - 1) * sides, 0) + 1e-9) << ring;
}

TEST(HeatWeights, TorusWeightsFromItsOwnSkeleton) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  medial::SkeletonByContractionParameters p;
  p.computeWeights = true;
  p.targetNodes = 8;  // bones of about 1.6, three times the tube radius: each owns the middle of its part
  const auto r = medial::skeletonByContraction(torus, p);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.weights.rows(), torus.vertices.rows());
  ASSERT_EQ(r.weights.cols(), r.skeleton.edgeCount());
  for (Eigen::Index j = 0; j < torus.vertices.rows(); ++j) EXPECT_NEAR(r.weights.row(j).sum(), 1.0, 1e-12);
  // Every bone drives some part of the surface.
  for (int bone = 0; bone < r.skeleton.edgeCount(); ++bone)
    EXPECT_GT(r.weights.col(bone).maxCoeff(), 0.5) << bone;
}

TEST(HeatWeights, ComponentNoBoneSeesStillGetsWeights) {
  // A second tube far from the skeleton: no bone is visible from it (every segment crosses the first
  // tube or leaves the mesh), the fallback weights it from its nearest bone.
  const medial::TriangleMesh mesh =
      appendMesh(tubeMesh(10, 1), tubeMesh(10, 1), Eigen::RowVector3d(0, 10, 0));
  const medial::InsideTest inside(mesh);
  const auto r = medial::heatWeights(mesh, twoBoneAxis(), inside);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.componentsWithoutSight, 1);
  for (Eigen::Index j = 0; j < mesh.vertices.rows(); ++j) EXPECT_NEAR(r.weights.row(j).sum(), 1.0, 1e-12);
}

TEST(HeatWeights, NoBonesIsAnError) {
  const medial::TriangleMesh tube = tubeMesh(10, 1);
  const medial::InsideTest inside(tube);
  medial::Skeleton lonely;
  lonely.nodes = {{0, 0, 0}};
  EXPECT_EQ(medial::heatWeights(tube, lonely, inside).error.message(),
            "the skeleton has no bones (edges) to weight");
}

TEST(HeatWeights, AbortStops) {
  const medial::TriangleMesh tube = tubeMesh(10, 1);
  const medial::InsideTest inside(tube);
  const auto r = medial::heatWeights(tube, twoBoneAxis(), inside, {}, [](double) { return false; });
  EXPECT_TRUE(r.error.isCancelled());
}

TEST(HeatWeights, AbortBetweenTheBonesSolvesStops) {
  // Eight bones are solved two at a time; an abort asked for after the factorization stops at the next block.
  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  medial::SkeletonByContractionParameters p;
  p.targetNodes = 8;
  const auto skeleton = medial::skeletonByContraction(torus, p);
  ASSERT_TRUE(skeleton.ok()) << skeleton.error;
  ASSERT_GT(skeleton.skeleton.edgeCount(), 2);
  const medial::InsideTest inside(torus);
  double last = 0;
  const auto r = medial::heatWeights(torus, skeleton.skeleton, inside, {}, [&](double f) {
    last = f;
    return f <= 0.5;
  });
  EXPECT_TRUE(r.error.isCancelled());
  EXPECT_GT(last, 0.5);
  EXPECT_LT(last, 0.9);
}
