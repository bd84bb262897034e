#include "engine/math/sphere_line_integral.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace pyro {

bool sphere_chord(const ConeSphere& s, const glm::dvec3& o, const glm::dvec3& w, double& a,
                  double& b, double& extinction) {
  const glm::dvec3 to_centre = s.c - o;
  const double tc = glm::dot(to_centre, w);
  const double d2 = std::max(glm::dot(to_centre, to_centre) - tc * tc, 0.0);
  if (!(s.r > 0.0) || d2 >= s.r * s.r) return false;
  const double h = std::sqrt(s.r * s.r - d2);
  a = tc - h;
  b = tc + h;
  extinction = s.k * (1.0 - std::sqrt(d2) / s.r);
  return true;
}

double sphere_optical_depth(const ConeSphere& s, const glm::dvec3& o, const glm::dvec3& w,
                            double a, double b) {
  double enter, leave, extinction;
  if (!sphere_chord(s, o, w, enter, leave, extinction)) return 0.0;
  const double inside = std::min(b, leave) - std::max(a, enter);
  return inside > 0.0 ? extinction * inside : 0.0;
}

}  // namespace pyro
