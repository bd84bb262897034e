// The Jacobi eigen-decomposition against matrices built from known eigenpairs, and its
// invariants: A V = V diag(values), V orthonormal with det +1, values sorted.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>

#include "engine/core/rng.h"
#include "engine/math/symmetric_eigen.h"

namespace pyro {
namespace {

glm::dmat3 from_eigenpairs(const glm::dmat3& v, const glm::dvec3& values) {
  glm::dmat3 d(0.0);
  for (int i = 0; i < 3; ++i) d[i][i] = values[i];
  return v * d * glm::transpose(v);
}

TEST(SymmetricEigen, RecoversKnownEigenpairsOfRandomRotations) {
  Rng rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const glm::dquat q = glm::normalize(glm::dquat(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
    const glm::dmat3 v = glm::mat3_cast(q);
    const glm::dvec3 values(std::exp(3.0 * rng.uniform()), std::exp(-2.0 * rng.uniform()), 1e-3 + rng.uniform());
    const SymmetricEigen e = symmetric_eigen(from_eigenpairs(v, values));
    glm::dvec3 sorted = values;
    if (sorted[0] < sorted[1]) std::swap(sorted[0], sorted[1]);
    if (sorted[1] < sorted[2]) std::swap(sorted[1], sorted[2]);
    if (sorted[0] < sorted[1]) std::swap(sorted[0], sorted[1]);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(e.values[i], sorted[i], 1e-9 * sorted[0]);
    EXPECT_NEAR(glm::determinant(e.vectors), 1.0, 1e-12);
    const glm::dmat3 back = from_eigenpairs(e.vectors, e.values);
    const glm::dmat3 a = from_eigenpairs(v, values);
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) EXPECT_NEAR(back[c][r], a[c][r], 1e-9 * sorted[0]);
  }
}

TEST(SymmetricEigen, DiagonalAndRepeatedValues) {
  const SymmetricEigen d = symmetric_eigen(glm::dmat3(2, 0, 0, 0, 5, 0, 0, 0, 3));
  EXPECT_DOUBLE_EQ(d.values[0], 5.0);
  EXPECT_DOUBLE_EQ(d.values[1], 3.0);
  EXPECT_DOUBLE_EQ(d.values[2], 2.0);
  EXPECT_NEAR(std::abs(d.vectors[0].y), 1.0, 1e-15);
  const SymmetricEigen s = symmetric_eigen(glm::dmat3(4.0));
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(s.values[i], 4.0);
  // A 2x2 block with equal diagonal: the rotation by 45 degrees.
  const SymmetricEigen b = symmetric_eigen(glm::dmat3(1, 2, 0, 2, 1, 0, 0, 0, 0.5));
  EXPECT_NEAR(b.values[0], 3.0, 1e-14);
  EXPECT_NEAR(b.values[1], 0.5, 1e-14);
  EXPECT_NEAR(b.values[2], -1.0, 1e-14);
  EXPECT_NEAR(std::abs(b.vectors[0].x), std::sqrt(0.5), 1e-14);
}

}  // namespace
}  // namespace pyro
