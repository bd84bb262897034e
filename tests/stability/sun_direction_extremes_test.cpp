// The sun straight overhead, below the horizon (light travelling up), on the horizon, and exactly
// along the camera's view axis from in front and from behind: the light phase builds its
// light-space frame from the light's direction alone. A frame made by crossing the light with the
// world's up axis (the naive choice) is a zero vector normalised, NaN, when the sun is overhead or
// straight below; the engine picks the axis least parallel to the light
// (engine/math/shadow_ray_index.h, orthonormal_basis). Each direction's opacity shadow map of one
// Gaussian holds its closed form: nothing on the sunward side, tau0 exp(-d^2 / (2 s^2)) past it,
// d the column's distance from the centre's line (gaussian_line_integral.h: tau0 = -ln(1 - rho)
// along an axis through the centre).
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "engine/math/gaussian_line_integral.h"
#include "engine/math/shadow_ray_index.h"
#include "systems/shadowing/opacity_shadow_map.h"

namespace pyro {
namespace {

glm::dvec3 stability_texel_centre(const ShadowVolume& map, int i, int j, int k) {
  const glm::vec3 t((i + 0.5f) / map.size.x, (j + 0.5f) / map.size.y, (k + 0.5f) / map.size.z);
  return glm::dvec3(glm::inverse(map.world_to_texture) * glm::vec4(t, 1.0f));
}

struct SunCase {
  const char* name;
  glm::dvec3 travel;
};

void PrintTo(const SunCase& c, std::ostream* os) { *os << c.name; }

class StabilitySunDirection : public ::testing::TestWithParam<SunCase> {};

TEST_P(StabilitySunDirection, OneGaussiansShadowMapIsItsClosedForm) {
  const glm::dvec3 centre(0.5, 4.0, -1.0);
  const double radius = 0.6, density = 0.7, tau0 = -std::log(1.0 - density), s = radius / 3.0;
  const std::vector<ShadowCaster> one{clamped_gaussian(centre, radius, density)};
  const glm::dvec3 w = glm::normalize(GetParam().travel);
  ShadowVolume map;
  build_opacity_shadow_map(one, GetParam().travel, {32, 16}, map);
  ASSERT_FALSE(map.empty());
  for (float v : map.optical_depth) ASSERT_TRUE(std::isfinite(v));
  double largest = 0.0;
  for (int j = 0; j < map.size.y; ++j)
    for (int i = 0; i < map.size.x; ++i) {
      EXPECT_EQ(map.optical_depth[size_t(j) * map.size.x + i], 0.0f) << "sunward of the particle";
      const glm::dvec3 p = stability_texel_centre(map, i, j, map.size.z - 1);
      const glm::dvec3 across = (p - centre) - glm::dot(p - centre, w) * w;
      const double d2 = glm::dot(across, across);
      // Within the particle's cube across an axis-aligned light, the column holds the whole line.
      const glm::dvec3 a = glm::abs(across);
      const double want = std::max({a.x, a.y, a.z}) < 3.0 * s ? tau0 * std::exp(-d2 / (2.0 * s * s)) : 0.0;
      const float got = map.optical_depth[(size_t(map.size.z - 1) * map.size.y + j) * map.size.x + i];
      ASSERT_NEAR(got, want, 1e-4 * tau0) << GetParam().name << " texel " << i << " " << j;
      largest = std::max(largest, double(got));
    }
  EXPECT_GT(largest, 0.95 * tau0);  // a column passes close to the centre
  // Sampled as GL samples it, beyond the particle along the light through its centre: the peak
  // interpolated between the four columns around it, each about a tenth of s off the line.
  EXPECT_NEAR(sample_optical_depth(map, glm::vec3(centre + 5.0 * radius * w)), tau0, 0.05 * tau0);
  EXPECT_EQ(sample_optical_depth(map, glm::vec3(centre - 5.0 * radius * w)), 0.0f);
}

// The exact shadow rays see the same depth from each direction.
TEST_P(StabilitySunDirection, ShadowRaysAgreeWithTheClosedForm) {
  const glm::dvec3 centre(0.5, 4.0, -1.0);
  const double radius = 0.6, density = 0.7, tau0 = -std::log(1.0 - density);
  const std::vector<ShadowCaster> one{clamped_gaussian(centre, radius, density)};
  const ShadowRayIndex rays(one, GetParam().travel);
  const glm::dvec3 w = glm::normalize(GetParam().travel);
  EXPECT_NEAR(rays.optical_depth_to_light(centre + 5.0 * radius * w), tau0, 1e-9);
  EXPECT_EQ(rays.optical_depth_to_light(centre - 5.0 * radius * w), 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    OverheadBelowHorizonAndAlongTheView, StabilitySunDirection,
    ::testing::Values(SunCase{"Overhead", {0.0, -1.0, 0.0}}, SunCase{"BelowTheHorizon", {0.0, 1.0, 0.0}},
                      SunCase{"AlmostOverhead", {1e-12, -1.0, 0.0}}, SunCase{"OnTheHorizon", {1.0, 0.0, 0.0}},
                      SunCase{"BehindTheCamera", {0.0, 0.0, -1.0}}, SunCase{"InFrontOfTheCamera", {0.0, 0.0, 1.0}}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace pyro
