#include "engine/math/sphere_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace pyro {

double sphere_field_profile(double x) {
  x = std::abs(x);
  if (x >= 1.0) return 0.0;
  if (x == 0.0) return std::numeric_limits<double>::infinity();
  const double m = std::sqrt(1.0 - x * x);
  const double e = std::comp_ellint_2(m), k = std::comp_ellint_1(m);
  return std::max(0.0, 1.0 - (2.0 / std::numbers::pi) * (2.0 * e - k));
}

namespace {

constexpr int kSphereFieldIntervals = 4096;

// g(x) + (2 / pi) ln x at x = i / kSphereFieldIntervals; its limit at 0.
std::vector<double> sphere_field_remainders() {
  std::vector<double> r(kSphereFieldIntervals + 1);
  r[0] = 1.0 + (2.0 / std::numbers::pi) * (std::log(4.0) - 2.0);
  for (int i = 1; i <= kSphereFieldIntervals; ++i) {
    const double x = double(i) / kSphereFieldIntervals;
    r[i] = sphere_field_profile(x) + (2.0 / std::numbers::pi) * std::log(x);
  }
  return r;
}

}  // namespace

double sphere_field_profile_tabulated(double x) {
  static const std::vector<double> table = sphere_field_remainders();
  x = std::abs(x);
  if (x >= 1.0) return 0.0;
  if (x == 0.0) return std::numeric_limits<double>::infinity();
  const double f = x * kSphereFieldIntervals;
  const int i = std::min(int(f), kSphereFieldIntervals - 1);
  const double t = f - i;
  const double remainder = table[i] * (1.0 - t) + table[i + 1] * t;
  return std::max(0.0, remainder - (2.0 / std::numbers::pi) * std::log(x));
}

}  // namespace pyro
