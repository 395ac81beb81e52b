/// \file
/// NormalMatrix: the matrix of the contraction's normal equations (5), W_L^2 L^T L + diag(W_H^2), rebuilt
/// every iteration. L is the cotangent Laplacian of a mesh whose connectivity never changes, so the
/// pattern of L L (the two-ring) is found once; each iteration only multiplies the values into it
/// (Gustavson's column-by-column product with the pattern known). Eigen's general sparse product finds
/// the pattern anew each time and sorts it, which costs more than the Cholesky factorization.
#pragma once

#include <Eigen/Sparse>

#include <vector>

namespace medial {

/// The normal equations' matrix of the contraction, its pattern found once (see the file).
class NormalMatrix {
 public:
  /// The pattern of `laplacian` squared. Every later `laplacian` must have this one's pattern.
  explicit NormalMatrix(const Eigen::SparseMatrix<double>& laplacian);

  /// weight^2 L L + diag(attraction^2), in the pattern found at construction.
  const Eigen::SparseMatrix<double>& update(const Eigen::SparseMatrix<double>& laplacian, double weight,
                                            const Eigen::VectorXd& attraction);

 private:
  Eigen::SparseMatrix<double> matrix_;
  Eigen::Index laplacianEntries_;  ///< the pattern's size (a cheap check that it is the same)
  std::vector<int> diagonal_;      ///< per column, the position of its diagonal entry in the values
  std::vector<int> position_;      ///< per row, its position in the column being filled
};

}  // namespace medial
