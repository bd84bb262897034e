#include "engine/math/symmetric_eigen.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/matrix.hpp>

namespace pyro {

namespace {

// One Jacobi rotation in the (p, q) plane that zeroes m[p][q] (glm: m[column][row]; m is kept
// symmetric), accumulated into v's columns (Golub & Van Loan, algorithm 8.5.1, sym.schur2).
void jacobi_rotate(glm::dmat3& m, glm::dmat3& v, int p, int q) {
  const double apq = m[q][p];
  if (apq == 0.0) return;
  const double tau = (m[q][q] - m[p][p]) / (2.0 * apq);
  const double t = (tau >= 0.0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1.0 + tau * tau));
  const double c = 1.0 / std::sqrt(1.0 + t * t), s = t * c;
  for (int k = 0; k < 3; ++k) {  // m <- m J: columns p and q
    const double mkp = m[p][k], mkq = m[q][k];
    m[p][k] = c * mkp - s * mkq;
    m[q][k] = s * mkp + c * mkq;
  }
  for (int k = 0; k < 3; ++k) {  // m <- J^T m: rows p and q
    const double mpk = m[k][p], mqk = m[k][q];
    m[k][p] = c * mpk - s * mqk;
    m[k][q] = s * mpk + c * mqk;
  }
  for (int k = 0; k < 3; ++k) {
    const double vkp = v[p][k], vkq = v[q][k];
    v[p][k] = c * vkp - s * vkq;
    v[q][k] = s * vkp + c * vkq;
  }
}

}  // namespace

SymmetricEigen symmetric_eigen(const glm::dmat3& a) {
  glm::dmat3 m = a;
  for (int c = 0; c < 3; ++c)
    for (int r = c + 1; r < 3; ++r) m[c][r] = m[r][c];  // symmetric from the upper triangle
  glm::dmat3 v(1.0);
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = m[1][0] * m[1][0] + m[2][0] * m[2][0] + m[2][1] * m[2][1];
    const double diag = m[0][0] * m[0][0] + m[1][1] * m[1][1] + m[2][2] * m[2][2];
    if (off <= 1e-30 * diag || off == 0.0) break;
    jacobi_rotate(m, v, 0, 1);
    jacobi_rotate(m, v, 0, 2);
    jacobi_rotate(m, v, 1, 2);
  }
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return m[i][i] > m[j][j]; });
  SymmetricEigen out;
  for (int i = 0; i < 3; ++i) {
    out.values[i] = m[order[i]][order[i]];
    out.vectors[i] = v[order[i]];
  }
  if (glm::determinant(out.vectors) < 0.0) out.vectors[2] = -out.vectors[2];
  return out;
}

}  // namespace pyro
