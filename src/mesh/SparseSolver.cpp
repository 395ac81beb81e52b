#include "mesh/SparseSolver.h"

#include <iostream>  // <Eigen/MetisSupport> uses std::cerr without including it

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/MetisSupport>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <Eigen/SparseQR>

#include <amd.h>

#include <utility>

namespace medial {

using SpMat = Eigen::SparseMatrix<double>;

namespace {

// SuiteSparse's AMD as an Eigen ordering: the same approximate minimum degree as Eigen's AMDOrdering (a
// port of CSparse's), faster, with factors of about the same size (docs/measurements.md). Eigen's
// AMDOrdering is the fallback should SuiteSparse refuse the pattern.
template <typename StorageIndex>
struct SuiteSparseAmdOrdering {
  static_assert(sizeof(StorageIndex) == sizeof(int), "amd_order takes int indices");
  using PermutationType = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, StorageIndex>;
  // `matrix`: both triangles of a symmetric pattern (what Eigen's simplicial solvers pass an ordering).
  template <typename MatrixType>
  void operator()(const MatrixType& matrix, PermutationType& inversePermutation) {
    Eigen::SparseMatrix<double, Eigen::ColMajor, StorageIndex> pattern = matrix;
    pattern.makeCompressed();
    const StorageIndex n = StorageIndex(pattern.cols());
    inversePermutation.resize(n);
    // amd_order's P lists the rows in elimination order: Eigen's ordering functors return that inverse.
    const int status = amd_order(int(n), pattern.outerIndexPtr(), pattern.innerIndexPtr(),
                                 inversePermutation.indices().data(), nullptr, nullptr);
    if (status != AMD_OK && status != AMD_OK_BUT_JUMBLED)
      Eigen::AMDOrdering<StorageIndex>()(matrix, inversePermutation);
  }
};

}  // namespace

struct SparseSolver::Backend {
  virtual ~Backend() = default;
  virtual void analyze(const SpMat& m) = 0;
  virtual bool factorize(const SpMat& m) = 0;
  virtual bool solve(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x) = 0;
};

namespace {

// Any Eigen sparse solver with analyzePattern / factorize / solve / info.
template <class Solver>
struct EigenBackend : SparseSolver::Backend {
  Solver solver;
  void analyze(const SpMat& m) override { solver.analyzePattern(m); }
  bool factorize(const SpMat& m) override {
    solver.factorize(m);
    return solver.info() == Eigen::Success;
  }
  bool solve(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x) override {
    x = solver.solve(rhs);
    return solver.info() == Eigen::Success;
  }
};

// CHOLMOD's supernodal LLT with one forced ordering (CHOLMOD otherwise tries several and keeps the best).
struct CholmodBackend : EigenBackend<Eigen::CholmodSupernodalLLT<SpMat, Eigen::Lower>> {
  explicit CholmodBackend(int ordering) {
    cholmod_common& common = solver.cholmod();
    common.nmethods = 1;
    common.method[0].ordering = ordering;
    common.postorder = 1;
  }
};

// SparseQR needs a compressed column-major matrix and has no separate analysis of a symmetric input.
struct QrBackend : EigenBackend<Eigen::SparseQR<SpMat, Eigen::COLAMDOrdering<int>>> {};

// Conjugate gradients preconditioned by an incomplete Cholesky factorization (Eigen's, with its own
// diagonal shift when a pivot would not be positive). Unpreconditioned CG stalled on the contraction's
// normal equations once W_L had grown (the elephant at iteration 10): their condition number grows with it.
struct CgBackend
    : EigenBackend<
          Eigen::ConjugateGradient<SpMat, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>>> {
  CgBackend() {
    solver.setTolerance(1e-8);
    solver.setMaxIterations(100000);
  }
};

std::unique_ptr<SparseSolver::Backend> makeBackend(SparseSolverKind kind) {
  using Kind = SparseSolverKind;
  switch (kind) {
    case Kind::Automatic:  // chosen by SparseSolver::analyze
      return nullptr;
    case Kind::CholmodSupernodalMetis:
      return std::make_unique<CholmodBackend>(CHOLMOD_METIS);
    case Kind::CholmodSupernodalAmd:
      return std::make_unique<CholmodBackend>(CHOLMOD_AMD);
    case Kind::SimplicialLltAmd:
      return std::make_unique<
          EigenBackend<Eigen::SimplicialLLT<SpMat, Eigen::Lower, SuiteSparseAmdOrdering<int>>>>();
    case Kind::SimplicialLdltAmd:
      return std::make_unique<
          EigenBackend<Eigen::SimplicialLDLT<SpMat, Eigen::Lower, SuiteSparseAmdOrdering<int>>>>();
    case Kind::SimplicialLltMetis:
      return std::make_unique<
          EigenBackend<Eigen::SimplicialLLT<SpMat, Eigen::Lower, Eigen::MetisOrdering<int>>>>();
    case Kind::SimplicialLdltMetis:
      return std::make_unique<
          EigenBackend<Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::MetisOrdering<int>>>>();
    case Kind::LuColamd:
      return std::make_unique<EigenBackend<Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>>>>();
    case Kind::LuAmd:
      return std::make_unique<EigenBackend<Eigen::SparseLU<SpMat, Eigen::AMDOrdering<int>>>>();
    case Kind::LuMetis:
      return std::make_unique<EigenBackend<Eigen::SparseLU<SpMat, Eigen::MetisOrdering<int>>>>();
    case Kind::QrColamd:
      return std::make_unique<QrBackend>();
    case Kind::ConjugateGradient:
      return std::make_unique<CgBackend>();
  }
  return nullptr;
}

const std::pair<SparseSolverKind, const char*> kNames[] = {
    {SparseSolverKind::Automatic, "auto"},
    {SparseSolverKind::CholmodSupernodalMetis, "cholmod-metis"},
    {SparseSolverKind::CholmodSupernodalAmd, "cholmod-amd"},
    {SparseSolverKind::SimplicialLltAmd, "llt-amd"},
    {SparseSolverKind::SimplicialLdltAmd, "ldlt-amd"},
    {SparseSolverKind::SimplicialLltMetis, "llt-metis"},
    {SparseSolverKind::SimplicialLdltMetis, "ldlt-metis"},
    {SparseSolverKind::LuColamd, "lu-colamd"},
    {SparseSolverKind::LuAmd, "lu-amd"},
    {SparseSolverKind::LuMetis, "lu-metis"},
    {SparseSolverKind::QrColamd, "qr-colamd"},
    {SparseSolverKind::ConjugateGradient, "cg"},
};

}  // namespace

std::string sparseSolverName(SparseSolverKind kind) {
  for (const auto& [k, name] : kNames)
    if (k == kind) return name;
  return "unknown";
}

bool parseSparseSolverKind(const std::string& name, SparseSolverKind& kind) {
  for (const auto& [k, n] : kNames)
    if (name == n) {
      kind = k;
      return true;
    }
  return false;
}

std::vector<SparseSolverKind> allSparseSolverKinds() {
  std::vector<SparseSolverKind> kinds;
  for (const auto& entry : kNames) kinds.push_back(entry.first);
  return kinds;
}

std::vector<std::string> sparseSolverNames() {
  std::vector<std::string> names;
  for (const auto& entry : kNames) names.push_back(entry.second);
  return names;
}

SparseSolver::SparseSolver(SparseSolverKind kind) : kind_(kind), chosen_(kind), backend_(makeBackend(kind)) {}
SparseSolver::~SparseSolver() = default;

void SparseSolver::analyze(const SpMat& matrix) {
  if (kind_ == SparseSolverKind::Automatic) {
    const bool sparse = double(matrix.nonZeros()) < kAmdBelowDensity * double(matrix.cols());
    chosen_ = matrix.rows() < kSimplicialBelow ? SparseSolverKind::SimplicialLltAmd
              : sparse                         ? SparseSolverKind::CholmodSupernodalAmd
                                               : SparseSolverKind::CholmodSupernodalMetis;
    backend_ = makeBackend(chosen_);
  }
  backend_->analyze(matrix);
}

bool SparseSolver::factorize(const SpMat& matrix) {
  if (backend_->factorize(matrix)) return true;
  error_ =
      sparseSolverName(chosen_) + ": the factorization failed (matrix not positive definite or singular)";
  return false;
}

bool SparseSolver::solve(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& solution) {
  if (backend_->solve(rhs, solution) && solution.allFinite()) return true;
  error_ = sparseSolverName(chosen_) + ": the solve failed or gave non-finite values";
  return false;
}

}  // namespace medial
