#include "contraction/NormalMatrix.h"

#include <algorithm>
#include <stdexcept>

namespace medial {

namespace {

// The pattern of L L, sorted by row in each column, with every diagonal entry (a column of an unused
// vertex is empty in L: its diagonal takes the attraction). Found column by column, as the product is
// then filled: Eigen's general product sorts through two transposes, which cost as much as several
// factorizations.
Eigen::SparseMatrix<double> twoRingPattern(const Eigen::SparseMatrix<double>& laplacian) {
  if (!laplacian.isCompressed() || laplacian.rows() != laplacian.cols())
    throw std::logic_error("NormalMatrix: the Laplacian must be square and compressed");
  const int n = int(laplacian.cols());
  const int* lOuter = laplacian.outerIndexPtr();
  const int* lRows = laplacian.innerIndexPtr();
  std::vector<int> outer(size_t(n) + 1, 0), rows, seenIn(size_t(n), -1);
  rows.reserve(size_t(laplacian.nonZeros()) * 3);
  for (int j = 0; j < n; ++j) {
    const size_t first = rows.size();
    seenIn[size_t(j)] = j;
    rows.push_back(j);
    for (int q = lOuter[j]; q < lOuter[j + 1]; ++q) {
      const int k = lRows[q];
      for (int r = lOuter[k]; r < lOuter[k + 1]; ++r)
        if (seenIn[size_t(lRows[r])] != j) {
          seenIn[size_t(lRows[r])] = j;
          rows.push_back(lRows[r]);
        }
    }
    std::sort(rows.begin() + std::ptrdiff_t(first), rows.end());
    outer[size_t(j) + 1] = int(rows.size());
  }
  const std::vector<double> zeros(rows.size(), 0.0);
  return Eigen::Map<const Eigen::SparseMatrix<double>>(n, n, Eigen::Index(rows.size()), outer.data(),
                                                       rows.data(), zeros.data());
}

}  // namespace

NormalMatrix::NormalMatrix(const Eigen::SparseMatrix<double>& laplacian)
    : matrix_(twoRingPattern(laplacian)),
      laplacianEntries_(laplacian.nonZeros()),
      position_(size_t(laplacian.rows()), -1) {
  diagonal_.assign(size_t(matrix_.cols()), -1);
  for (Eigen::Index j = 0; j < matrix_.outerSize(); ++j)
    for (Eigen::Index p = matrix_.outerIndexPtr()[j]; p < matrix_.outerIndexPtr()[j + 1]; ++p)
      if (matrix_.innerIndexPtr()[p] == j) diagonal_[size_t(j)] = p;
}

const Eigen::SparseMatrix<double>& NormalMatrix::update(const Eigen::SparseMatrix<double>& laplacian,
                                                        double weight, const Eigen::VectorXd& attraction) {
  if (!laplacian.isCompressed() || laplacian.cols() != matrix_.cols() ||
      laplacian.nonZeros() != laplacianEntries_)
    throw std::logic_error("NormalMatrix: the Laplacian's pattern changed");
  const int* outer = matrix_.outerIndexPtr();
  const int* rows = matrix_.innerIndexPtr();
  double* values = matrix_.valuePtr();
  const int* lOuter = laplacian.outerIndexPtr();
  const int* lRows = laplacian.innerIndexPtr();
  const double* lValues = laplacian.valuePtr();
  const double square = weight * weight;
  for (Eigen::Index j = 0; j < matrix_.cols(); ++j) {
    for (Eigen::Index p = outer[j]; p < outer[j + 1]; ++p) {
      position_[size_t(rows[p])] = p;
      values[p] = 0;
    }
    // Column j of L L: the columns k of L weighted by L_kj.
    for (Eigen::Index q = lOuter[j]; q < lOuter[j + 1]; ++q) {
      const int k = lRows[q];
      const double lkj = square * lValues[q];
      for (Eigen::Index r = lOuter[k]; r < lOuter[k + 1]; ++r)
        values[position_[size_t(lRows[r])]] += lValues[r] * lkj;
    }
    values[diagonal_[size_t(j)]] += attraction[j] * attraction[j];
  }
  return matrix_;
}

}  // namespace medial
