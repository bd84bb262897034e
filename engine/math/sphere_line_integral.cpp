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

double sphere_opacity_area(double r, double k) {
  if (!(r > 0.0) || !(k > 0.0)) return 0.0;
  // 16-point Gauss-Legendre on [0, 1] in x = d / r (Abramowitz & Stegun 25.4.30), in
  // symmetric pairs about 1/2; the integrand's square-root end point at x = 1 costs it under 1e-4.
  static constexpr double nodes[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
                                      0.6178762444026438, 0.7554044083550030, 0.8656312023878318,
                                      0.9445750230732326, 0.9894009349916499};
  static constexpr double weights[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
                                        0.1495959888165767, 0.1246289712555339, 0.0951585116824928,
                                        0.0622535239386479, 0.0271524594117541};
  const double pi = 3.14159265358979323846;
  double sum = 0.0;
  for (int i = 0; i < 8; ++i)
    for (const double sign : {-1.0, 1.0}) {
      const double x = 0.5 + 0.5 * sign * nodes[i];
      const double depth = k * (1.0 - x) * 2.0 * r * std::sqrt(std::max(1.0 - x * x, 0.0));
      sum += 0.5 * weights[i] * (1.0 - std::exp(-depth)) * 2.0 * pi * x;
    }
  return sum * r * r;
}

}  // namespace pyro
