#include "ContractionTestMeshes.h"
#include "mesh/MeshDecimation.h"
#include "mesh/MeshTopology.h"

#include <gtest/gtest.h>

using medial::testing::appendMesh;
using medial::testing::topologyOf;
using medial::testing::torusMesh;
using medial::testing::tubeMesh;
using medial::testing::withFin;

TEST(MeshDecimation, TorusGoesToTheBudgetKeepingItsGenus) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5, 96, 32);  // 3072 vertices
  const medial::DecimatedMesh coarse = medial::decimateMesh(torus, 500);
  ASSERT_TRUE(coarse.decimated) << coarse.note;
  EXPECT_LE(coarse.mesh.vertices.rows(), 510);
  EXPECT_GE(coarse.mesh.vertices.rows(), 400);
  const medial::MeshTopology t = topologyOf(coarse.mesh);
  EXPECT_TRUE(t.isClosedManifold());
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.genus, 1);
  EXPECT_EQ(t.unusedVertices, 0);
  // Every input vertex went into a coarse vertex nearby: the chain of collapses that carried it may drift
  // a little further than the coarse mesh's spacing (~0.3 here), never across the torus.
  ASSERT_EQ(coarse.representative.size(), size_t(torus.vertices.rows()));
  for (Eigen::Index v = 0; v < torus.vertices.rows(); ++v) {
    const int r = coarse.representative[size_t(v)];
    ASSERT_GE(r, 0);
    ASSERT_LT(r, coarse.mesh.vertices.rows());
    EXPECT_LT((coarse.mesh.vertices.row(r) - torus.vertices.row(v)).norm(), 1.0);
  }
  for (Eigen::Index v = 0; v < coarse.mesh.vertices.rows(); ++v) {
    const Eigen::RowVector3d p = coarse.mesh.vertices.row(v);
    EXPECT_NEAR(std::hypot(std::hypot(p.x(), p.y()) - 2.0, p.z()), 0.5, 0.05) << p;
  }
}

TEST(MeshDecimation, EachComponentKeepsItsTopology) {
  const auto mesh =
      appendMesh(torusMesh(2, 0.5, 96, 32), tubeMesh(6, 0.8, 80, 24), Eigen::RowVector3d(10, 0, 0));
  const medial::DecimatedMesh coarse = medial::decimateMesh(mesh, 800);
  ASSERT_TRUE(coarse.decimated) << coarse.note;
  const medial::MeshTopology t = topologyOf(coarse.mesh);
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.genus, 1);
  EXPECT_TRUE(t.isClosedManifold());
}

TEST(MeshDecimation, MeshWithinTheBudgetIsLeftAlone) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  const medial::DecimatedMesh coarse = medial::decimateMesh(torus, 4000);
  EXPECT_FALSE(coarse.decimated);
  EXPECT_EQ(coarse.mesh.vertices, torus.vertices);
  for (size_t v = 0; v < coarse.representative.size(); ++v) EXPECT_EQ(coarse.representative[v], int(v));
  EXPECT_FALSE(medial::decimateMesh(torus, 0).decimated);  // 0: no budget
}

TEST(MeshDecimation, NonManifoldOrMisorientedMeshIsDecimatedFromARepairedCopy) {
  medial::TriangleMesh torus = withFin(torusMesh(2, 0.5, 96, 32));  // a fin
  std::swap(torus.faces(5, 1), torus.faces(5, 2));  // and one face turned against its neighbours
  const medial::DecimatedMesh coarse = medial::decimateMesh(torus, 500);
  ASSERT_TRUE(coarse.decimated) << coarse.note;
  EXPECT_LE(coarse.mesh.vertices.rows(), 520);
  EXPECT_EQ(topologyOf(coarse.mesh).nonManifoldEdges, 0);
  for (int r : coarse.representative) {
    EXPECT_GE(r, 0);
    EXPECT_LT(r, coarse.mesh.vertices.rows());
  }
}

TEST(MeshDecimation, FacesRepeatingAVertexAreLeftOut) {
  medial::TriangleMesh torus = torusMesh(2, 0.5, 96, 32);
  torus.faces.conservativeResize(torus.faces.rows() + 1, 3);
  torus.faces.row(torus.faces.rows() - 1) << 0, 1, 1;
  const medial::DecimatedMesh coarse = medial::decimateMesh(torus, 500);
  ASSERT_TRUE(coarse.decimated) << coarse.note;
  EXPECT_EQ(topologyOf(coarse.mesh).genus, 1);
  for (int r : coarse.representative) EXPECT_GE(r, 0);
}
