#include "ContractionTestMeshes.h"
#include "mesh/MeshGeometry.h"

#include <gtest/gtest.h>

#include <vector>

// The cotangent Laplacian is built column by column (no triplet list): it must equal the sum over faces
// of the corner weights, with rows summing to 0, on a mesh with a degenerate face and an unused vertex.
TEST(MeshGeometry, LaplacianEqualsTheSumOfTheFacesCornerWeights) {
  medial::TriangleMesh torus = medial::testing::torusMesh(2, 0.5, 24, 8);
  torus.vertices.conservativeResize(torus.vertices.rows() + 1, 3);  // an unused vertex
  torus.vertices.row(torus.vertices.rows() - 1) << 9, 9, 9;
  torus.faces.conservativeResize(torus.faces.rows() + 1, 3);  // a face repeating a vertex
  torus.faces.row(torus.faces.rows() - 1) << 3, 3, 7;
  const Eigen::Index n = torus.vertices.rows();
  const Eigen::MatrixX3d cotangents = medial::faceCotangents(torus.vertices, torus.faces, 1.0 * M_PI / 180);
  const Eigen::SparseMatrix<double> laplacian = medial::laplacianFromCotangents(torus.faces, cotangents, n);

  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index f = 0; f < torus.faces.rows(); ++f)
    for (int corner = 0; corner < 3; ++corner) {
      const int i = torus.faces(f, (corner + 1) % 3), j = torus.faces(f, (corner + 2) % 3);
      const double w = cotangents(f, corner);
      expected(i, j) += w;
      expected(j, i) += w;
      expected(i, i) -= w;
      expected(j, j) -= w;
    }
  EXPECT_LT((Eigen::MatrixXd(laplacian) - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((laplacian * Eigen::VectorXd::Ones(n)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(laplacian.col(n - 1).nonZeros(), 0);  // the unused vertex
  EXPECT_TRUE(laplacian.isCompressed());
  // Column entries are sorted (Eigen's solvers rely on it).
  for (Eigen::Index c = 0; c < n; ++c)
    for (int k = laplacian.outerIndexPtr()[c] + 1; k < laplacian.outerIndexPtr()[c + 1]; ++k)
      ASSERT_LT(laplacian.innerIndexPtr()[k - 1], laplacian.innerIndexPtr()[k]);
}

// The contraction's assembler refills the same pattern: equal to a fresh assembly, iteration after
// iteration, with the degenerate face and the unused vertex above.
TEST(MeshGeometry, AssemblerRefillsTheLaplacianOfNewCotangents) {
  medial::TriangleMesh torus = medial::testing::torusMesh(2, 0.5, 24, 8);
  torus.vertices.conservativeResize(torus.vertices.rows() + 1, 3);
  torus.vertices.row(torus.vertices.rows() - 1) << 9, 9, 9;
  torus.faces.conservativeResize(torus.faces.rows() + 1, 3);
  torus.faces.row(torus.faces.rows() - 1) << 3, 3, 7;
  const Eigen::Index n = torus.vertices.rows();
  medial::LaplacianAssembler assembler(torus.faces, n);
  medial::Vertices at = torus.vertices;
  for (int iteration = 0; iteration < 3; ++iteration) {
    at.col(0) *= 0.7;
    const Eigen::MatrixX3d cotangents = medial::faceCotangents(at, torus.faces, M_PI / 180);
    const Eigen::SparseMatrix<double> fresh = medial::laplacianFromCotangents(torus.faces, cotangents, n);
    const Eigen::SparseMatrix<double>& refilled = assembler.update(cotangents);
    ASSERT_EQ(refilled.nonZeros(), fresh.nonZeros());
    EXPECT_LT((Eigen::MatrixXd(refilled) - Eigen::MatrixXd(fresh)).cwiseAbs().maxCoeff(), 1e-12);
  }
}

// Meyer et al.'s mixed areas tile the surface: they sum to its area; on an equilateral triangle each corner
// takes a third, on a right-angled or obtuse one the corner at the large angle takes half.
TEST(MeshGeometry, MixedVoronoiAreasSumToTheSurfaceArea) {
  const medial::TriangleMesh torus = medial::testing::torusMesh(2, 0.5, 24, 8);
  const Eigen::VectorXd mixed = medial::mixedVoronoiAreas(torus.vertices, torus.faces);
  EXPECT_NEAR(mixed.sum(), medial::faceAreas(torus.vertices, torus.faces).sum(), 1e-9);
  EXPECT_GT(mixed.minCoeff(), 0);
  medial::Vertices triangle(3, 3);
  triangle << 0, 0, 0, 1, 0, 0, 0.5, std::sqrt(3.0) / 2, 0;
  const medial::Faces face = (medial::Faces(1, 3) << 0, 1, 2).finished();
  const Eigen::VectorXd thirds = medial::mixedVoronoiAreas(triangle, face);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(thirds[c], std::sqrt(3.0) / 12, 1e-12);
  triangle.row(2) << -0.2, 0.3, 0;  // obtuse at vertex 0
  const Eigen::VectorXd obtuse = medial::mixedVoronoiAreas(triangle, face);
  const double area = medial::faceAreas(triangle, face)[0];
  EXPECT_NEAR(obtuse[0], area / 2, 1e-12);
  EXPECT_NEAR(obtuse[1], area / 4, 1e-12);
}

TEST(MeshGeometry, VolumeCentroidIsTheCentreOfAClosedMeshAndOfAnOpenOne) {
  medial::TriangleMesh torus = medial::testing::torusMesh(2, 0.5, 24, 8);
  torus.vertices.rowwise() += Eigen::RowVector3d(3, -1, 7);
  const Eigen::Vector3d centre = medial::volumeCentroid(torus.vertices, torus.faces);
  EXPECT_LT((centre - Eigen::Vector3d(3, -1, 7)).norm(), 1e-9);
  medial::TriangleMesh tube = medial::testing::tubeMesh(10, 1);
  tube.vertices.rowwise() += Eigen::RowVector3d(0, 0, 4);
  EXPECT_LT((medial::volumeCentroid(tube.vertices, tube.faces) - Eigen::Vector3d(0, 0, 4)).norm(), 1e-6);
  tube.faces.conservativeResize(2 * 39 * 16, 3);  // without its caps: open, no volume, its faces' centre
  EXPECT_LT((medial::volumeCentroid(tube.vertices, tube.faces) - Eigen::Vector3d(0, 0, 4)).norm(), 1e-6);
}
