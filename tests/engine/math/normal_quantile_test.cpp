#include "engine/math/normal_quantile.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pyro {
namespace {

// Phi(u) from the library's erfc: the independent reference.
double normal_cdf(double u) { return 0.5 * std::erfc(-u / std::sqrt(2.0)); }

TEST(NormalQuantile, InvertsTheNormalCdfWithinTheBoundOfItsFormula) {
  double worst = 0.0;
  for (double u = -7.0; u <= 7.0; u += 0.01) worst = std::max(worst, std::abs(normal_quantile(normal_cdf(u)) - u));
  EXPECT_LT(worst, 4.5e-4);
  EXPECT_GT(worst, 1e-5);  // a rational approximation, not the exact inverse
  EXPECT_NEAR(normal_quantile(0.975), 1.959964, 4.5e-4);
  EXPECT_NEAR(normal_quantile(0.5), 0.0, 4.5e-4);
}

// The fraction of the light a Gaussian of column depth tau sends the eye from in front of depth
// `end`: the light from depth u is tau phi(u) exp(-tau Phi(u)) du, over its total 1 - e^-tau, by
// midpoint integration on a fine grid.
double light_in_front_of(double end, double tau) {
  double sum = 0.0;
  const double du = 1e-4;
  for (double u = -9.0; u < end; u += du) {
    const double mid = u + 0.5 * du;
    sum += tau * std::exp(-0.5 * mid * mid) / std::sqrt(2.0 * M_PI) * std::exp(-tau * normal_cdf(mid)) * du;
  }
  return sum / -std::expm1(-tau);
}

TEST(NormalQuantile, SeenDepthIsTheQuantileOfTheLightTheEyeReceives) {
  for (double q : {0.25, 0.5, 0.75})
    for (double tau : {0.01, 0.5, 2.3, 10.0, 27.6})
      EXPECT_NEAR(light_in_front_of(seen_depth(tau, q), tau), q, 2e-3) << "tau " << tau << ", q " << q;
  EXPECT_NEAR(seen_depth(0.0), 0.0, 4.5e-4);
  EXPECT_LT(seen_depth(27.6), -1.9);  // a dense particle is seen on its near side
}

}  // namespace
}  // namespace pyro
