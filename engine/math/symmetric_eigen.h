#pragma once
// Eigen-decomposition of a real symmetric 3x3 matrix by cyclic Jacobi rotations (Golub & Van Loan,
// "Matrix Computations", 4th ed., section 8.5.2): each rotation zeroes one off-diagonal pair, and
// the off-diagonal norm falls quadratically once it is small. Used to turn a covariance into the
// rotation and three standard deviations of an anisotropic Gaussian particle.
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace pyro {

struct SymmetricEigen {
  glm::dvec3 values{0.0};  // in decreasing order
  glm::dmat3 vectors{1.0};  // column i is the unit eigenvector of values[i]; det = +1
};

// a must be symmetric (only its upper triangle is read). a = V diag(values) V^T to rounding.
SymmetricEigen symmetric_eigen(const glm::dmat3& a);

}  // namespace pyro
