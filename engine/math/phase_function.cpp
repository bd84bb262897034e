#include "engine/math/phase_function.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pyro {

namespace {
constexpr double inv_4pi = 0.25 * std::numbers::inv_pi;
}

double henyey_greenstein(double mu, double g) {
  const double d = 1.0 + g * g - 2.0 * g * mu;
  return inv_4pi * (1.0 - g * g) / (d * std::sqrt(d));
}

double sample_henyey_greenstein_cosine(double g, double xi) {
  if (std::abs(g) < 1e-4) return 1.0 - 2.0 * xi;
  const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * xi);
  return std::clamp((1.0 + g * g - s * s) / (2.0 * g), -1.0, 1.0);
}

double cornette_shanks(double mu, double g) {
  const double d = 1.0 + g * g - 2.0 * g * mu;
  return inv_4pi * 3.0 * (1.0 - g * g) * (1.0 + mu * mu) / (2.0 * (2.0 + g * g) * d * std::sqrt(d));
}

double cornette_shanks_mean_cosine(double g) {
  return 3.0 * g * (4.0 + g * g) / (5.0 * (2.0 + g * g));
}

double phase(PhaseFunction f, double mu, double g) {
  return f == PhaseFunction::henyey_greenstein ? henyey_greenstein(mu, g) : cornette_shanks(mu, g);
}

const char* phase_function_name(PhaseFunction f) {
  return f == PhaseFunction::henyey_greenstein ? "henyey-greenstein" : "cornette-shanks";
}

bool parse_phase_function(std::string_view name, PhaseFunction& out) {
  if (name == "henyey-greenstein") out = PhaseFunction::henyey_greenstein;
  else if (name == "cornette-shanks") out = PhaseFunction::cornette_shanks;
  else return false;
  return true;
}

SphereIntegral integrate_over_sphere(PhaseFunction f, double g, int cos_intervals, int azimuth_steps) {
  if (cos_intervals < 2 || cos_intervals % 2 != 0 || azimuth_steps < 1)
    throw std::invalid_argument("integrate_over_sphere: cos_intervals must be even and >= 2");
  // An oblique incoming direction, unit length.
  const double in_len = std::sqrt(0.3 * 0.3 + 0.5 * 0.5 + 0.8 * 0.8);
  const double wx = 0.3 / in_len, wy = -0.5 / in_len, wz = 0.8 / in_len;
  const double h = 2.0 / cos_intervals;
  const double dphi = 2.0 * std::numbers::pi / azimuth_steps;
  SphereIntegral s;
  for (int i = 0; i <= cos_intervals; ++i) {
    const double cz = -1.0 + i * h;
    const double sz = std::sqrt(std::max(0.0, 1.0 - cz * cz));
    const double simpson = (i == 0 || i == cos_intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    double ring = 0.0, ring_mu = 0.0;
    for (int k = 0; k < azimuth_steps; ++k) {
      const double phi = (k + 0.5) * dphi;
      const double mu = wx * sz * std::cos(phi) + wy * sz * std::sin(phi) + wz * cz;
      const double p = phase(f, mu, g);
      ring += p;
      ring_mu += p * mu;
    }
    s.integral += simpson * ring;
    s.mean_cosine += simpson * ring_mu;
  }
  s.integral *= h / 3.0 * dphi;
  s.mean_cosine *= h / 3.0 * dphi;
  return s;
}

}  // namespace pyro
