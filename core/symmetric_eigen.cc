#include "core/symmetric_eigen.h"

#include <Eigen/Eigenvalues>

namespace corridor {

Eigen::Vector2d SmallestEigenvector(const Eigen::Matrix2d& symmetric) {
  // Eigenvalues in increasing order: the first column belongs to the smallest.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(symmetric);
  return solver.eigenvectors().col(0);
}

}  // namespace corridor
