#include "contraction/NormalMatrix.h"

#include <algorithm>
#include <stdexcept>

namespace medial {

NormalMatrix::NormalMatrix(const Eigen::SparseMatrix<double>& laplacian)
    : matrix_(laplacian * laplacian), laplacianEntries_(laplacian.nonZeros()), position_(size_t(laplacian.rows()), -1) {
  matrix_.makeCompressed();
  diagonal_.assign(size_t(matrix_.cols()), -1);
  for (Eigen::Index j = 0; j < matrix_.outerSize(); ++j)
    for (Eigen::Index p = matrix_.outerIndexPtr()[j]; p < matrix_.outerIndexPtr()[j + 1]; ++p)
      if (matrix_.innerIndexPtr()[p] == j) diagonal_[size_t(j)] = p;
  // A column without a diagonal entry has an empty column in L: give it one (the attraction goes there).
  if (std::find(diagonal_.begin(), diagonal_.end(), -1) != diagonal_.end()) {
    Eigen::SparseMatrix<double> identity(matrix_.rows(), matrix_.cols());
    identity.setIdentity();
    matrix_ = matrix_ + identity;
    matrix_.makeCompressed();
    for (Eigen::Index j = 0; j < matrix_.outerSize(); ++j)
      for (Eigen::Index p = matrix_.outerIndexPtr()[j]; p < matrix_.outerIndexPtr()[j + 1]; ++p)
        if (matrix_.innerIndexPtr()[p] == j) diagonal_[size_t(j)] = p;
  }
}

const Eigen::SparseMatrix<double>& NormalMatrix::update(const Eigen::SparseMatrix<double>& laplacian,
                                                        double weight, const Eigen::VectorXd& attraction) {
  if (!laplacian.isCompressed() || laplacian.cols() != matrix_.cols() || laplacian.nonZeros() != laplacianEntries_)
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
      for (Eigen::Index r = lOuter[k]; r < lOuter[k + 1]; ++r) values[position_[size_t(lRows[r])]] += lValues[r] * lkj;
    }
    values[diagonal_[size_t(j)]] += attraction[j] * attraction[j];
  }
  return matrix_;
}

}  // namespace medial
