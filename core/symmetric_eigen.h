#ifndef CORRIDOR_CORE_SYMMETRIC_EIGEN_H_
#define CORRIDOR_CORE_SYMMETRIC_EIGEN_H_

#include <Eigen/Core>

namespace corridor {

// The unit eigenvector of a symmetric 2x2 matrix's smallest eigenvalue: the normal of the line
// that best fits points whose scatter matrix it is. One translation unit instantiates Eigen's
// eigen solver, which takes long to compile, for every caller.
Eigen::Vector2d SmallestEigenvector(const Eigen::Matrix2d& symmetric);

}  // namespace corridor

#endif  // CORRIDOR_CORE_SYMMETRIC_EIGEN_H_
