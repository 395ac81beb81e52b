/// \file
/// SparseSolver: one interface over the sparse solvers of the contraction paper's study (Table I):
/// Cholesky (CHOLMOD supernodal; Eigen simplicial LLT / LDLT), LU and QR, each with a fill-reducing
/// ordering (METIS, AMD, COLAMD), plus conjugate gradients as the iterative alternative.
///
/// The contraction solves a symmetric positive definite system whose sparsity pattern never changes, so the
/// symbolic analysis (ordering, elimination tree, supernodes) runs once in analyze() and each iteration only
/// calls factorize() and solve().
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

namespace medial {

/// The sparse direct (and one iterative) solvers of the normal equations, benchmarked against each
/// other (bench/, docs/measurements.md).
enum class SparseSolverKind {
  /// Default: Eigen's simplicial LLT with AMD below kSimplicialBelow unknowns, CHOLMOD supernodal with METIS
  /// (the paper's winner) from there on: the supernodes' BLAS calls cost more than they save while small.
  /// (Choosing AMD or METIS per matrix by the fill of both analyses costs more in METIS's analysis than
  /// it saves below kSimplicialBelow.) CHOLMOD's OpenBLAS threads also slow down badly when the other
  /// core is busy; the simplicial one does not. A sparser matrix than the contraction's two-ring one (fewer
  /// than kAmdBelowDensity entries per column on average: the heat weights' one-ring Laplacian) takes AMD
  /// instead of METIS, whose analysis of such a matrix costs more than the factorization saves. The
  /// figures behind these thresholds: docs/measurements.md.
  Automatic,
  CholmodSupernodalMetis,
  CholmodSupernodalAmd,
  SimplicialLltAmd,
  SimplicialLdltAmd,
  SimplicialLltMetis,
  SimplicialLdltMetis,
  LuColamd,
  LuAmd,
  LuMetis,
  QrColamd,
  ConjugateGradient,
};

constexpr int kSimplicialBelow = 30000;  ///< see SparseSolverKind::Automatic
constexpr double kAmdBelowDensity = 12;  ///< entries per column (one-ring Laplacian: about 7, two-ring: 19)

///@{
/// Short names used on the command line and in benchmarks: auto, cholmod-metis, cholmod-amd, llt-amd,
/// ldlt-amd, llt-metis, ldlt-metis, lu-colamd, lu-amd, lu-metis, qr-colamd, cg.
std::string sparseSolverName(SparseSolverKind kind);
bool parseSparseSolverKind(const std::string& name, SparseSolverKind& kind);
std::vector<SparseSolverKind> allSparseSolverKinds();
///@}
/// Every name, in the order above (the one list the filter, the command line and the GUI offer).
std::vector<std::string> sparseSolverNames();

/// One interface over Eigen's and CHOLMOD's factorizations: analyze once, factorize and solve for each
/// matrix of the same pattern.
class SparseSolver {
 public:
  /// A solver of the given kind (Automatic chooses at analyze()).
  explicit SparseSolver(SparseSolverKind kind = SparseSolverKind::Automatic);
  ~SparseSolver();
  SparseSolver(const SparseSolver&) = delete;
  SparseSolver& operator=(const SparseSolver&) = delete;

  /// The kind asked for.
  SparseSolverKind kind() const { return kind_; }
  /// The solver in use: kind() itself, or for Automatic the one analyze() chose.
  SparseSolverKind chosen() const { return chosen_; }
  /// Symbolic analysis of the pattern of a symmetric matrix (both triangles stored).
  void analyze(const Eigen::SparseMatrix<double>& matrix);
  /// Numeric factorization; false (with error()) when the matrix is not positive definite or singular.
  bool factorize(const Eigen::SparseMatrix<double>& matrix);
  /// Solves for every column of rhs; false (with error()) on failure.
  bool solve(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& solution);
  /// The last failure's message.
  const std::string& error() const { return error_; }

  struct Backend;

 private:
  SparseSolverKind kind_, chosen_;
  std::unique_ptr<Backend> backend_;
  std::string error_;
};

}  // namespace medial
