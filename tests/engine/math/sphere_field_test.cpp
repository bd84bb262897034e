// The sphere's field (engine/math/sphere_field.h) against what it was derived to give: its line
// integral at every miss distance d is the explosion model's k (1 - d/r) 2 sqrt(r^2 - d^2)
// (engine/math/sphere_line_integral.h), measured by a midpoint sum along the chord.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/math/sphere_field.h"
#include "engine/math/sphere_line_integral.h"

namespace pyro {
namespace {

// The field of the unit sphere integrated along the chord at miss distance d (n midpoints).
double sphere_field_chord_sum(double d, int n) {
  const double h = std::sqrt(1.0 - d * d), dt = 2.0 * h / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double t = -h + (i + 0.5) * dt;
    sum += sphere_field_profile(std::sqrt(d * d + t * t)) * dt;
  }
  return sum;
}

TEST(SphereField, ProjectsToTheBillboardsModelAtEveryDistance) {
  for (double d : {0.02, 0.1, 0.25, 0.5, 0.75, 0.9, 0.98}) {
    const double expected = (1.0 - d) * 2.0 * std::sqrt(1.0 - d * d);
    EXPECT_NEAR(sphere_field_chord_sum(d, 200000), expected, 2e-4 * std::max(expected, 0.05)) << "d = " << d;
  }
}

TEST(SphereField, AgreesWithTheSphereLineIntegral) {
  const ConeSphere s{glm::dvec3(0.0), 2.0, 0.7};
  const double d = 0.6;  // miss distance in world units, 0.3 of the radius
  const double model = sphere_optical_depth(s, glm::dvec3(-5.0, d, 0.0), glm::dvec3(1.0, 0.0, 0.0), 0.0, 10.0);
  // The field scales as k g(rho / r), its chord as r: the line integral is k r times the unit one.
  EXPECT_NEAR(s.k * s.r * sphere_field_chord_sum(d / s.r, 200000), model, 1e-4 * model);
}

TEST(SphereField, IsZeroAtAndPastTheRimAndPositiveInside) {
  EXPECT_EQ(sphere_field_profile(1.0), 0.0);
  EXPECT_EQ(sphere_field_profile(1.5), 0.0);
  EXPECT_NEAR(sphere_field_profile(0.999), 0.75 * (1.0 - 0.999 * 0.999), 1e-4);  // 3 (1 - x^2) / 4 near the rim
  for (double x = 0.01; x < 1.0; x += 0.01) EXPECT_GT(sphere_field_profile(x), 0.0) << x;
  EXPECT_TRUE(std::isinf(sphere_field_profile(0.0)));
}

TEST(SphereField, TheTableFollowsTheEllipticIntegrals) {
  double worst = 0.0;
  for (double x = 1e-5; x < 1.0; x += 0.000731) {
    const double exact = sphere_field_profile(x);
    worst = std::max(worst, std::abs(sphere_field_profile_tabulated(x) - exact) / std::max(exact, 1e-3));
  }
  EXPECT_LT(worst, 2e-4);
  EXPECT_EQ(sphere_field_profile_tabulated(1.0), 0.0);
}

}  // namespace
}  // namespace pyro
