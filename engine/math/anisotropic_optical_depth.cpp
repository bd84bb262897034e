#include "engine/math/anisotropic_optical_depth.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace pyro {

glm::dmat3 whitening_matrix(const AnisotropicGaussian& g) {
  const glm::dquat q = glm::normalize(glm::dquat(g.rotation.w, g.rotation.x, g.rotation.y, g.rotation.z));
  const glm::dmat3 r = glm::mat3_cast(q);  // columns: the local axes in world space
  // Row i of M is local axis i over its scale; glm matrices are indexed [column][row].
  glm::dmat3 m(0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[j][i] = r[i][j] / double(g.scale[i]);
  return m;
}

AnisotropicRaySegment anisotropic_ray_segment(const AnisotropicGaussian& g, const glm::dvec3& o,
                                              const glm::dvec3& w) {
  const glm::dmat3 m = whitening_matrix(g);
  return anisotropic_ray_segment(m, m * (o - glm::dvec3(g.centre)), double(g.extinction), w);
}

AnisotropicRaySegment anisotropic_ray_segment(const glm::dmat3& m, const glm::dvec3& u0, double k,
                                              const glm::dvec3& w) {
  AnisotropicRaySegment s;
  const glm::dvec3 v = m * w;
  const double a = glm::dot(v, v);
  if (!(a > 0.0) || !(k > 0.0)) return s;
  const double tc = -glm::dot(u0, v) / a;
  const glm::dvec3 closest = u0 + tc * v;
  const double m2_min = glm::dot(closest, closest);
  const double e2 = double(kAnisotropicExtent) * double(kAnisotropicExtent);
  if (!(m2_min < e2)) return s;
  const double h = std::sqrt((e2 - m2_min) / a);
  s.hit = true;
  s.t_closest = tc;
  s.t_enter = tc - h;
  s.t_exit = tc + h;
  s.rate = std::sqrt(0.5 * a);
  s.peak = k * std::exp(-0.5 * m2_min) * std::sqrt(std::numbers::pi / (2.0 * a));
  return s;
}

double AnisotropicRaySegment::depth(double a, double b) const {
  if (!hit) return 0.0;
  const double lo = std::max(a, t_enter), hi = std::min(b, t_exit);
  if (!(hi > lo)) return 0.0;
  return peak * (std::erf(rate * (hi - t_closest)) - std::erf(rate * (lo - t_closest)));
}

double anisotropic_optical_depth(const AnisotropicGaussian& g, const glm::dvec3& o,
                                 const glm::dvec3& w, double a, double b) {
  return anisotropic_ray_segment(g, o, w).depth(a, b);
}

double erf_as_7_1_26(double x) {
  const auto& c = kErfAs7126;
  const double ax = std::abs(x);
  const double t = 1.0 / (1.0 + c[0] * ax);
  const double poly = t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
  const double y = 1.0 - poly * std::exp(-ax * ax);
  return x < 0.0 ? -y : y;
}

}  // namespace pyro
