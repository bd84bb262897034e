#include "engine/math/projected_ellipsoid.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace pyro {

namespace {

// <a, b> = a^T D b, D = diag(1, 1, 1, -1).
double dot_d(const glm::dvec4& a, const glm::dvec4& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z - a.w * b.w;
}

glm::dvec4 row(const glm::dmat4& m, int i) { return {m[0][i], m[1][i], m[2][i], m[3][i]}; }

// True when the plane p certainly misses the unit sphere and the centre is on its positive
// side; a relative margin makes near-tangent planes count as cutting (the safe side).
bool wholly_positive(const glm::dvec4& p) {
  return p.w > 0.0 && glm::length(glm::dvec3(p)) < p.w * (1.0 - 1e-9);
}

// The pair of roots of <r4, r4> l^2 - 2 <r, r4> l + <r, r> = 0, ascending.
glm::dvec2 edge_pair(const glm::dvec4& r, const glm::dvec4& r4) {
  const double a = dot_d(r4, r4), b = dot_d(r, r4), c = dot_d(r, r);
  const double root = std::sqrt(std::max(b * b - a * c, 0.0));
  const double l0 = (b - root) / a, l1 = (b + root) / a;
  return {std::min(l0, l1), std::max(l0, l1)};
}

}  // namespace

ProjectedEllipsoid project_ellipsoid(const AnisotropicGaussian& g, const glm::dmat4& view_projection) {
  const glm::dquat q = glm::normalize(glm::dquat(g.rotation.w, g.rotation.x, g.rotation.y, g.rotation.z));
  const glm::dmat3 r = glm::mat3_cast(q);
  glm::dmat4 m(1.0);
  for (int i = 0; i < 3; ++i) m[i] = glm::dvec4(r[i] * (double(kAnisotropicExtent) * double(g.scale[i])), 0.0);
  m[3] = glm::dvec4(glm::dvec3(g.centre), 1.0);
  const glm::dmat4 t = view_projection * m;
  const glm::dvec4 r1 = row(t, 0), r2 = row(t, 1), r3 = row(t, 2), r4 = row(t, 3);
  ProjectedEllipsoid out;
  const glm::dvec4 near_plane = r3 + r4;
  if (near_plane.w > 0.0) out.depth_ndc = r3.w / r4.w;  // centre beyond the near plane
  if (wholly_positive(near_plane)) {
    out.cover = EllipsoidCover::rectangle;
    const glm::dvec2 x = edge_pair(r1, r4), y = edge_pair(r2, r4);
    out.lo = {x[0], y[0]};
    out.hi = {x[1], y[1]};
  } else if (wholly_positive(-r4)) {
    out.cover = EllipsoidCover::hidden;
  } else {
    out.cover = EllipsoidCover::full_screen;
  }
  return out;
}

}  // namespace pyro
