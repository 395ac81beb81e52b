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
