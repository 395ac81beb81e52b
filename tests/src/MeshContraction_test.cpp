#include "ContractionTestMeshes.h"
#include "contraction/MeshContraction.h"
#include "mesh/MeshGeometry.h"
#include "mesh/SparseSolver.h"

#include <gtest/gtest.h>

#include <cmath>

using medial::testing::torusMesh;
using medial::testing::tubeMesh;

TEST(CotangentLaplacian, EquilateralTriangleWeightsAndZeroRowSums) {
  medial::Vertices v(3, 3);
  v << 0, 0, 0, 1, 0, 0, 0.5, std::sqrt(3.0) / 2, 0;
  medial::Faces f(1, 3);
  f << 0, 1, 2;
  const Eigen::MatrixXd L = medial::cotangentLaplacian(v, f, 1e-3).toDense();
  EXPECT_NEAR(L(0, 1), 1 / std::sqrt(3.0), 1e-12);  // cot 60 degrees
  EXPECT_NEAR((L - L.transpose()).norm(), 0, 1e-12);
  EXPECT_NEAR(L.rowwise().sum().norm(), 0, 1e-12);
}

TEST(CotangentLaplacian, DegenerateTriangleStaysFinite) {
  medial::Vertices v(3, 3);
  v << 0, 0, 0, 1, 0, 0, 2, 0, 0;  // collinear: zero area
  medial::Faces f(1, 3);
  f << 0, 1, 2;
  const Eigen::MatrixXd L = medial::cotangentLaplacian(v, f, M_PI / 180).toDense();
  EXPECT_TRUE(L.allFinite());
  EXPECT_NEAR(std::abs(L(0, 2)), 1 / std::tan(M_PI / 180), 1e-6);  // the 180-degree angle, clamped
}

TEST(SparseSolver, EverySolverSolvesTheContractionSystem) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5, 16, 8);
  const Eigen::SparseMatrix<double> L = medial::cotangentLaplacian(torus.vertices, torus.faces, 1e-3);
  Eigen::SparseMatrix<double> A = L * L;
  for (int i = 0; i < A.rows(); ++i) A.coeffRef(i, i) += 1.0;
  const Eigen::MatrixXd b = torus.vertices;
  for (medial::SparseSolverKind kind : medial::allSparseSolverKinds()) {
    medial::SparseSolver solver(kind);
    solver.analyze(A);
    ASSERT_TRUE(solver.factorize(A)) << medial::sparseSolverName(kind);
    Eigen::MatrixXd x;
    ASSERT_TRUE(solver.solve(b, x)) << medial::sparseSolverName(kind);
    EXPECT_LT((A * x - b).norm() / b.norm(), 1e-8) << medial::sparseSolverName(kind);
  }
}

// auto: Eigen's simplicial LLT below kSimplicialBelow unknowns, CHOLMOD supernodal above - with METIS for
// the contraction's two-ring matrix, AMD for a sparser one (SparseSolver.h has the measurements).
TEST(SparseSolver, AutomaticChoosesBySizeAndDensity) {
  auto banded = [](int n, int halfWidth) {
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < n; ++i)
      for (int j = std::max(0, i - halfWidth); j <= std::min(n - 1, i + halfWidth); ++j)
        entries.emplace_back(i, j, i == j ? 4.0 * halfWidth : -1.0);
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(entries.begin(), entries.end());
    return A;
  };
  const std::pair<Eigen::SparseMatrix<double>, medial::SparseSolverKind> cases[] = {
      {banded(medial::kSimplicialBelow - 1, 9), medial::SparseSolverKind::SimplicialLltAmd},
      {banded(medial::kSimplicialBelow, 9), medial::SparseSolverKind::CholmodSupernodalMetis},
      {banded(medial::kSimplicialBelow, 3), medial::SparseSolverKind::CholmodSupernodalAmd}};
  for (const auto& [A, expected] : cases) {
    medial::SparseSolver solver;
    solver.analyze(A);
    EXPECT_EQ(solver.chosen(), expected) << A.rows() << " unknowns, " << A.nonZeros() << " entries";
  }
}

TEST(SparseSolver, NamesRoundTrip) {
  for (medial::SparseSolverKind kind : medial::allSparseSolverKinds()) {
    medial::SparseSolverKind parsed;
    ASSERT_TRUE(medial::parseSparseSolverKind(medial::sparseSolverName(kind), parsed));
    EXPECT_EQ(parsed, kind);
  }
  medial::SparseSolverKind unused;
  EXPECT_FALSE(medial::parseSparseSolverKind("magic", unused));
}

TEST(MeshContraction, TubeShrinksToItsAxis) {
  const medial::TriangleMesh tube = tubeMesh(10, 1);
  const medial::ContractionResult r = medial::contractMesh(tube);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_LT(r.volumeRatio, 0.01);
  // Every vertex ends near the x axis, and the tube keeps most of its length.
  const Eigen::VectorXd distanceToAxis = r.contracted.rightCols(2).rowwise().norm();
  EXPECT_LT(distanceToAxis.maxCoeff(), 0.2);
  EXPECT_GT(r.contracted.col(0).maxCoeff() - r.contracted.col(0).minCoeff(), 7.0);
}

TEST(MeshContraction, SameResultAtAnyScale) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  const medial::ContractionResult reference = medial::contractMesh(torus);
  for (double scale : {1e-3, 1e3}) {
    medial::TriangleMesh scaled = torus;
    scaled.vertices *= scale;
    const medial::ContractionResult r = medial::contractMesh(scaled);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.iterations, reference.iterations);
    // Same up to rounding (a symmetric torus is sensitive to it once degenerate): 1e-3 of its size 5.
    EXPECT_LT((r.contracted / scale - reference.contracted).cwiseAbs().maxCoeff(), 5e-3);
  }
}

TEST(MeshContraction, AbortStopsWithAnError) {
  const medial::ContractionResult r =
      medial::contractMesh(torusMesh(2, 0.5), {}, [](double) { return false; });
  EXPECT_TRUE(r.error.isCancelled());
}

// The paper's W_L0 (~ sqrt of the mean face area) makes a finer mesh's first iterations idle: four times
// the vertices, three more iterations (MeshContraction.h). Above referenceVertices W_L0 is scaled so that a
// torus at four times the resolution contracts in about as many iterations as at the reference.
TEST(MeshContraction, AFinerMeshContractsInAsManyIterations) {
  const medial::TriangleMesh coarse = torusMesh(2, 0.5, 48, 16), fine = torusMesh(2, 0.5, 96, 32);
  medial::ContractionParameters p;
  p.referenceVertices = int(coarse.vertices.rows());
  const medial::ContractionResult atReference = medial::contractMesh(coarse, p);
  const medial::ContractionResult scaled = medial::contractMesh(fine, p);
  p.referenceVertices = 0;  // the paper's W_L0 at every resolution
  const medial::ContractionResult unscaled = medial::contractMesh(fine, p);
  ASSERT_TRUE(atReference.ok() && scaled.ok() && unscaled.ok());
  EXPECT_LE(scaled.iterations, atReference.iterations + 1);
  EXPECT_GE(unscaled.iterations, scaled.iterations + 2);
  // W_L0 never starts above the W_L cap, however small the reference.
  p.referenceVertices = 1;
  p.recordSteps = true;
  const medial::ContractionResult capped = medial::contractMesh(fine, p);
  ASSERT_TRUE(capped.ok()) << capped.error;
  EXPECT_EQ(capped.steps.front().contractionWeight, p.maxContractionWeight);
  // And it still contracts onto the torus' core circle (radius 2 in the xy plane).
  for (const auto* r : {&atReference, &scaled}) {
    const Eigen::VectorXd ring = r->contracted.leftCols(2).rowwise().norm();
    EXPECT_LT((ring.array() - 2).abs().maxCoeff(), 0.1);
    EXPECT_LT(r->contracted.col(2).cwiseAbs().maxCoeff(), 0.1);
  }
}
