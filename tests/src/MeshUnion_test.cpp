// MeshUnion: CGAL corefinement of closed meshes into one, with part labels; and the inputs it refuses.
#include "ContractionTestMeshes.h"
#include "mesh/MeshGeometry.h"
#include "mesh/MeshTopology.h"
#include "mesh/MeshUnion.h"
#include "mesh/SelfIntersections.h"

#include <gtest/gtest.h>

#include <cmath>

using medial::testing::tubeMesh;

namespace {

medial::TriangleMesh moved(medial::TriangleMesh mesh, const Eigen::RowVector3d& by) {
  mesh.vertices.rowwise() += by;
  return mesh;
}

medial::TriangleMesh rotatedAboutZ(medial::TriangleMesh mesh, double radians) {
  const Eigen::Matrix3d r = Eigen::AngleAxisd(radians, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  mesh.vertices = (mesh.vertices * r.transpose()).eval();
  return mesh;
}

medial::MeshTopology topologyOf(const medial::TriangleMesh& mesh) {
  std::vector<std::vector<int64_t>> faces;
  for (int f = 0; f < mesh.faces.rows(); ++f)
    faces.push_back({mesh.faces(f, 0), mesh.faces(f, 1), mesh.faces(f, 2)});
  return medial::computeMeshTopology(mesh.vertices.rows(), faces);
}

double volumeOf(const medial::TriangleMesh& mesh) {
  return medial::enclosedVolume(mesh.vertices, mesh.faces);
}

std::vector<std::pair<int, int>> cuts(const medial::TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> points(size_t(mesh.vertices.rows()));
  for (size_t v = 0; v < points.size(); ++v) points[v] = mesh.vertices.row(Eigen::Index(v)).transpose();
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < mesh.faces.rows(); ++f)
    faces.push_back({mesh.faces(f, 0), mesh.faces(f, 1), mesh.faces(f, 2)});
  return medial::selfIntersectingFaces(points, faces);
}

}  // namespace

// A cross of two tubes: one closed sphere-like surface, no face cutting another, each vertex labelled with
// the tube it lies on.
TEST(MeshUnion, CrossOfTwoTubesIsOneClosedManifold) {
  const medial::TriangleMesh a = tubeMesh(10, 1), b = rotatedAboutZ(tubeMesh(6, 0.7), M_PI / 2 + 0.1);
  const medial::MeshUnionResult r = medial::meshUnion({a, b});
  ASSERT_TRUE(r.ok()) << r.error;
  const auto t = topologyOf(r.mesh);
  EXPECT_EQ(t.borderEdges, 0);
  EXPECT_EQ(t.nonManifoldEdges, 0);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.eulerCharacteristic, 2);
  EXPECT_TRUE(cuts(r.mesh).empty());
  ASSERT_EQ(r.vertexLabel.size(), size_t(r.mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < r.mesh.vertices.rows(); ++v) {
    const Eigen::RowVector3d p = r.mesh.vertices.row(v);
    // Far along x only tube a is there; far along the rotated axis only tube b.
    if (std::abs(p.x()) > 3) {
      EXPECT_EQ(r.vertexLabel[size_t(v)], 0) << p;
    }
    if (std::abs(p.y()) > 2) {
      EXPECT_EQ(r.vertexLabel[size_t(v)], 1) << p;
    }
  }
  // The union's volume is less than the sum of the two (they share their crossing).
  const double sum = volumeOf(a) + volumeOf(b), joined = volumeOf(r.mesh);
  EXPECT_LT(joined, sum - 1.0);
  EXPECT_GT(joined, volumeOf(a));
}

TEST(MeshUnion, SeparatePartsStaySeparateAndAPartInsideVanishes) {
  const medial::TriangleMesh a = tubeMesh(4, 1);
  const medial::MeshUnionResult apart = medial::meshUnion({a, moved(a, {0, 5, 0})});
  ASSERT_TRUE(apart.ok()) << apart.error;
  EXPECT_EQ(topologyOf(apart.mesh).components, 2);
  const medial::MeshUnionResult inside = medial::meshUnion({a, tubeMesh(2, 0.5)});
  ASSERT_TRUE(inside.ok()) << inside.error;
  EXPECT_EQ(inside.mesh.vertices.rows(), a.vertices.rows());
}

TEST(MeshUnion, OpenOrSelfCuttingPartsAreErrorsAndInwardPartsAreTurned) {
  medial::TriangleMesh open = tubeMesh(4, 1);
  open.faces.conservativeResize(open.faces.rows() - 1, 3);
  EXPECT_NE(medial::meshUnion({tubeMesh(4, 1), open}).error.message().find("part 2 is not a closed manifold"),
            std::string::npos);
  medial::TriangleMesh inverted = tubeMesh(4, 1);
  inverted.faces.col(1).swap(inverted.faces.col(2));
  const medial::MeshUnionResult turned = medial::meshUnion({inverted});
  ASSERT_TRUE(turned.ok()) << turned.error;
  EXPECT_GT(volumeOf(turned.mesh), 0) << "an inward part is turned outward";
  // A vertex pulled through the opposite wall: the part cuts itself and bounds no volume.
  const int sides = 16;
  medial::TriangleMesh twisted = tubeMesh(4, 1);
  twisted.vertices.row(sides) << -1.9, -1.5, 0;  // ring 1, from y = 1 to beyond y = -1
  EXPECT_NE(medial::meshUnion({twisted}).error.message().find("part 1 bounds no volume"), std::string::npos);
  EXPECT_TRUE(
      medial::meshUnion({tubeMesh(4, 1), tubeMesh(4, 1)}, [](double) { return false; }).error.isCancelled());
}
