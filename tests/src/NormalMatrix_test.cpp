#include "ContractionTestMeshes.h"
#include "contraction/NormalMatrix.h"
#include "mesh/MeshGeometry.h"

#include <gtest/gtest.h>

// The normal matrix filled into a fixed pattern equals Eigen's W_L^2 L L + diag(W_H^2), iteration after
// iteration as the cotangents change, on a mesh with an unused vertex (an empty column of L, whose row
// then holds only its attraction).
TEST(NormalMatrix, EqualsTheProductOfTheLaplacianWithItselfPlusTheAttraction) {
  medial::TriangleMesh torus = medial::testing::torusMesh(2, 0.5, 24, 8);
  torus.vertices.conservativeResize(torus.vertices.rows() + 1, 3);
  torus.vertices.row(torus.vertices.rows() - 1) << 9, 9, 9;
  const Eigen::Index n = torus.vertices.rows();
  const auto laplacianOf = [&](const medial::Vertices& at) {
    return medial::laplacianFromCotangents(torus.faces, medial::faceCotangents(at, torus.faces, M_PI / 180),
                                           n);
  };
  medial::NormalMatrix normal(laplacianOf(torus.vertices));
  medial::Vertices at = torus.vertices;
  for (int iteration = 0; iteration < 3; ++iteration) {
    at.col(2) *= 0.5;  // new cotangents, same pattern
    const Eigen::SparseMatrix<double> laplacian = laplacianOf(at);
    const Eigen::VectorXd attraction = Eigen::VectorXd::LinSpaced(n, 1, 3);
    const double weight = 0.25 * (iteration + 1);
    Eigen::MatrixXd expected = Eigen::MatrixXd(laplacian * laplacian) * weight * weight;
    expected.diagonal() += attraction.cwiseAbs2();
    const Eigen::SparseMatrix<double>& sparse = normal.update(laplacian, weight, attraction);
    Eigen::SparseMatrix<double> identity(n, n);
    identity.setIdentity();
    EXPECT_EQ(sparse.nonZeros(), Eigen::SparseMatrix<double>(laplacian * laplacian + identity).nonZeros());
    const Eigen::MatrixXd got = sparse;
    EXPECT_LT((got - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
    EXPECT_DOUBLE_EQ(got(n - 1, n - 1), 9.0);  // the unused vertex: its attraction only
  }
  // A Laplacian of another pattern is refused rather than written into the wrong entries.
  medial::TriangleMesh other = medial::testing::torusMesh(2, 0.5, 12, 8);
  other.vertices.conservativeResize(n, 3);
  const Eigen::SparseMatrix<double> wrong = medial::laplacianFromCotangents(
      other.faces, medial::faceCotangents(other.vertices, other.faces, M_PI / 180), n);
  EXPECT_THROW(normal.update(wrong, 1, Eigen::VectorXd::Ones(n)), std::logic_error);
}
