#include "ContractionTestMeshes.h"
#include "mesh/EdgeCoarsening.h"
#include "mesh/MeshDecimation.h"
#include "mesh/MeshTopology.h"

#include <gtest/gtest.h>

#include <cmath>

using medial::testing::appendMesh;
using medial::testing::topologyOf;
using medial::testing::torusMesh;
using medial::testing::tubeMesh;
using medial::testing::withFin;

namespace {

double torusDistance(const Eigen::RowVector3d& p, double R, double r) {
  return std::abs(std::hypot(std::hypot(p.x(), p.y()) - R, p.z()) - r);
}

}  // namespace

TEST(EdgeCoarsening, FineTorusComesDownToTheCountKeepingGenusAndShape) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5, 400, 100);  // 40,000 vertices
  const medial::CoarsenedMesh coarse = medial::coarsenEdges(torus, 4000);
  ASSERT_TRUE(coarse.ok);
  EXPECT_LE(coarse.mesh.vertices.rows(), 4000);
  EXPECT_GE(coarse.mesh.vertices.rows(), 3000);
  const medial::MeshTopology t = topologyOf(coarse.mesh);
  EXPECT_TRUE(t.isClosedManifold());
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.genus, 1);
  EXPECT_EQ(t.unusedVertices, 0);
  // Midpoints of short edges cut into a curved surface a little at each pass: the coarse vertices stay
  // within 6 % of the tube's radius of it (measured: 4 %), and every input vertex went into a coarse vertex
  // nearby.
  for (Eigen::Index v = 0; v < coarse.mesh.vertices.rows(); ++v)
    ASSERT_LT(torusDistance(coarse.mesh.vertices.row(v), 2, 0.5), 0.03) << v;
  ASSERT_EQ(coarse.representative.size(), size_t(torus.vertices.rows()));
  for (Eigen::Index v = 0; v < torus.vertices.rows(); ++v) {
    const int r = coarse.representative[size_t(v)];
    ASSERT_GE(r, 0);
    ASSERT_LT(r, coarse.mesh.vertices.rows());
    ASSERT_LT((coarse.mesh.vertices.row(r) - torus.vertices.row(v)).norm(), 0.5) << v;
  }
}

TEST(EdgeCoarsening, ComponentsKeepTheirTopology) {
  const auto mesh =
      appendMesh(torusMesh(2, 0.5, 200, 60), tubeMesh(6, 0.8, 200, 40), Eigen::RowVector3d(10, 0, 0));
  const medial::CoarsenedMesh coarse = medial::coarsenEdges(mesh, 1000);
  ASSERT_TRUE(coarse.ok);
  const medial::MeshTopology t = topologyOf(coarse.mesh);
  EXPECT_TRUE(t.isClosedManifold());
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.genus, 1);
}

TEST(EdgeCoarsening, NonManifoldMeshIsLeftToTheCaller) {
  const medial::TriangleMesh torus = withFin(torusMesh(2, 0.5, 96, 32));  // a third face on one edge
  EXPECT_FALSE(medial::coarsenEdges(torus, 500).ok);
  // The decimation then repairs a copy and collapses it as before.
  const medial::DecimatedMesh decimated = medial::decimateMesh(torus, 150);
  EXPECT_TRUE(decimated.decimated) << decimated.note;
  EXPECT_EQ(decimated.coarsenedVertices, 0);
}

TEST(EdgeCoarsening, DecimationOfALargeMeshGoesThroughItAndComposesTheRepresentatives) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5, 96, 32);  // 3072 vertices > 16 x 150
  const medial::DecimatedMesh coarse = medial::decimateMesh(torus, 150);
  ASSERT_TRUE(coarse.decimated) << coarse.note;
  EXPECT_GT(coarse.coarsenedVertices, 150);
  EXPECT_LE(coarse.coarsenedVertices, 1500);
  EXPECT_LE(coarse.mesh.vertices.rows(), 160);
  EXPECT_EQ(topologyOf(coarse.mesh).genus, 1);
  ASSERT_EQ(coarse.representative.size(), size_t(torus.vertices.rows()));
  for (Eigen::Index v = 0; v < torus.vertices.rows(); ++v) {
    const int r = coarse.representative[size_t(v)];
    ASSERT_GE(r, 0);
    ASSERT_LT(r, coarse.mesh.vertices.rows());
    EXPECT_LT((coarse.mesh.vertices.row(r) - torus.vertices.row(v)).norm(), 1.5);
  }
}
