// Phase functions (Umenhoffer et al. 2006, section 3.1): normalisation over the sphere and mean
// cosines against closed forms, by quadrature over the sphere of directions.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/math/phase_function.h"

namespace pyro {
namespace {

TEST(PhaseFunction, BothIntegrateToOneOverTheSphere) {
  for (PhaseFunction f : {PhaseFunction::henyey_greenstein, PhaseFunction::cornette_shanks}) {
    for (double g = -0.9; g <= 0.9 + 1e-9; g += 0.1) {
      const SphereIntegral s = integrate_over_sphere(f, g);
      EXPECT_NEAR(s.integral, 1.0, 1e-3) << phase_function_name(f) << " g=" << g;
      EXPECT_NEAR(s.integral, 1.0, 1e-6) << phase_function_name(f) << " g=" << g;  // in fact
    }
  }
}

TEST(PhaseFunction, HenyeyGreensteinMeanCosineIsG) {
  for (double g = -0.9; g <= 0.9 + 1e-9; g += 0.15)
    EXPECT_NEAR(integrate_over_sphere(PhaseFunction::henyey_greenstein, g).mean_cosine, g, 1e-6) << g;
}

TEST(PhaseFunction, CornetteShanksMeanCosineClosedForm) {
  for (double g = -0.9; g <= 0.9 + 1e-9; g += 0.15) {
    const double m = integrate_over_sphere(PhaseFunction::cornette_shanks, g).mean_cosine;
    EXPECT_NEAR(m, cornette_shanks_mean_cosine(g), 1e-6) << g;
  }
  EXPECT_NEAR(cornette_shanks_mean_cosine(0.5), 0.5666666666666667, 1e-15);
}

TEST(PhaseFunction, IsotropicAtZeroAndRayleighLikeCornetteShanks) {
  const double iso = 1.0 / (4.0 * std::numbers::pi);
  for (double mu : {-1.0, -0.3, 0.0, 0.6, 1.0}) {
    EXPECT_NEAR(henyey_greenstein(mu, 0.0), iso, 1e-15);
    // g = 0: Cornette–Shanks is the Rayleigh phase function 3 (1 + μ²) / (16π).
    EXPECT_NEAR(cornette_shanks(mu, 0.0), 3.0 * (1.0 + mu * mu) / (16.0 * std::numbers::pi), 1e-15);
  }
}

TEST(PhaseFunction, PapersFormulaIsCornetteShanks) {
  // Umenhoffer et al. 2006, section 3.1, as printed (and called Henyey–Greenstein there).
  auto paper = [](double mu, double g) {
    return 1.0 / (4.0 * std::numbers::pi) * 3.0 * (1.0 - g * g) * (1.0 + mu * mu) /
           (2.0 * (2.0 + g * g) * std::pow(1.0 + g * g - 2.0 * g * mu, 1.5));
  };
  for (double g : {-0.7, 0.0, 0.4, 0.85})
    for (double mu : {-1.0, -0.2, 0.5, 1.0}) {
      EXPECT_NEAR(paper(mu, g), cornette_shanks(mu, g), 1e-12);
      if (g != 0.0) {
        EXPECT_GT(std::abs(paper(mu, g) - henyey_greenstein(mu, g)), 1e-4) << g << " " << mu;
      }
    }
}

TEST(PhaseFunction, HenyeyGreensteinSamplesHaveItsMoments) {
  // Henyey–Greenstein's Legendre moments are g^l: E[μ] = g, E[P2(μ)] = E[(3μ² − 1) / 2] = g².
  // A stratified ξ over 200000 strata estimates both to better than 1e-4.
  for (double g : {-0.6, 0.0, 0.3, 0.85}) {
    const int n = 200000;
    double m1 = 0.0, m2 = 0.0;
    for (int i = 0; i < n; ++i) {
      const double mu = sample_henyey_greenstein_cosine(g, (i + 0.5) / n);
      ASSERT_GE(mu, -1.0);
      ASSERT_LE(mu, 1.0);
      m1 += mu;
      m2 += 0.5 * (3.0 * mu * mu - 1.0);
    }
    EXPECT_NEAR(m1 / n, g, 1e-4) << g;
    EXPECT_NEAR(m2 / n, g * g, 1e-4) << g;
  }
  EXPECT_DOUBLE_EQ(sample_henyey_greenstein_cosine(0.5, 0.0), -1.0);
}

}  // namespace
}  // namespace pyro
