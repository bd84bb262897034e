// The sun's scattering with a forward lobe and octaves of multiple scattering
// (engine/math/scattering_octaves.h) against its sum written out.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/math/phase_function.h"
#include "engine/math/scattering_octaves.h"

namespace pyro {
namespace {

TEST(ScatteringOctaves, OneIsotropicOctaveIsSingleScattering) {
  for (double tau : {0.0, 0.3, 2.5})
    for (double mu : {-1.0, 0.2, 1.0}) EXPECT_NEAR(sun_scattering({}, mu, tau), std::exp(-tau), 1e-14);
}

TEST(ScatteringOctaves, SumOfAttenuatedLobes) {
  SunScattering s;
  s.anisotropy = 0.7;
  s.octaves = {3, 0.25, 0.5, 0.4};
  const double mu = 0.9, tau = 1.7, four_pi = 4.0 * std::numbers::pi;
  const double want = four_pi * (henyey_greenstein(mu, 0.7) * std::exp(-tau) +
                                 0.5 * henyey_greenstein(mu, 0.28) * std::exp(-0.25 * tau) +
                                 0.25 * henyey_greenstein(mu, 0.112) * std::exp(-0.0625 * tau));
  EXPECT_NEAR(sun_scattering(s, mu, tau), want, 1e-12);
  // The later octaves carry light deeper than single scattering does.
  SunScattering single = s;
  single.octaves.octaves = 1;
  EXPECT_GT(sun_scattering(s, mu, 6.0), 5.0 * sun_scattering(single, mu, 6.0));
}

TEST(ScatteringOctaves, RejectsParametersOutOfRange) {
  SunScattering s;
  EXPECT_NO_THROW(validate(s));
  s.anisotropy = 1.0;
  EXPECT_THROW(validate(s), std::invalid_argument);
  s = {};
  s.octaves.octaves = 0;
  EXPECT_THROW(validate(s), std::invalid_argument);
  s = {};
  s.octaves.attenuation = 0.0;
  EXPECT_THROW(validate(s), std::invalid_argument);
  s = {};
  s.octaves.contribution = 1.5;
  EXPECT_THROW(validate(s), std::invalid_argument);
}

}  // namespace
}  // namespace pyro
