#include "engine/math/tabulated_erf.h"

#include <array>
#include <cmath>

namespace pyro {

namespace {

constexpr int kErfNodes = 8192;
constexpr double kErfReach = 4.0, kErfStep = 2.0 * kErfReach / kErfNodes;

const std::array<double, kErfNodes + 2>& erf_nodes() {
  static const std::array<double, kErfNodes + 2> nodes = [] {
    std::array<double, kErfNodes + 2> n{};
    for (int k = 0; k <= kErfNodes; ++k) n[size_t(k)] = std::erf(-kErfReach + k * kErfStep);
    n[kErfNodes + 1] = n[kErfNodes];  // so that x = kErfReach reads a valid pair
    return n;
  }();
  return nodes;
}

}  // namespace

double tabulated_erf(double x) {
  if (!(x > -kErfReach)) return x != x ? x : -1.0;
  if (x >= kErfReach) return 1.0;
  const double at = (x + kErfReach) / kErfStep;
  const int k = int(at);
  const double f = at - k;
  const std::array<double, kErfNodes + 2>& n = erf_nodes();
  return n[size_t(k)] + f * (n[size_t(k) + 1] - n[size_t(k)]);
}

}  // namespace pyro
