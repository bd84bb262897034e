// The opacity shadow map against the exact shadow rays: at every texel centre it holds the exact
// optical depth toward the light (its only error is interpolation between texels), outside the
// media across the light it reads nothing, and past them the whole column.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "engine/core/rng.h"
#include "engine/particles/anisotropic_gaussian.h"
#include "engine/math/shadow_ray_index.h"
#include "systems/shadowing/opacity_shadow_map.h"

namespace pyro {
namespace {

// Gaussians, every third particle of them (`other`) an explosion's sphere or a fitted import's
// anisotropic Gaussian.
enum class Other { none, spheres, ellipsoids };

std::vector<ShadowCaster> cloud(int n, Other other = Other::none) {
  Rng rng(5);
  std::vector<ShadowCaster> gs;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 c(rng.uniform(-2.0f, 2.0f), rng.uniform(3.0f, 4.0f), rng.uniform(-2.0f, 2.0f));
    const float radius = rng.uniform(0.2f, 0.6f), density = rng.uniform(0.1f, 0.5f);
    if (other == Other::spheres && i % 3 == 0) {
      gs.push_back(ConeSphere{c, radius, 4.0 * density});
    } else if (other == Other::ellipsoids && i % 3 == 0) {
      AnisotropicGaussian g;
      g.centre = glm::vec3(c);
      g.rotation = glm::normalize(glm::quat(rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f),
                                            rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f)));
      g.scale = glm::vec3(radius / 3.0f) * glm::vec3(rng.uniform(0.3f, 2.0f), rng.uniform(0.3f, 2.0f), 1.0f);
      g.extinction = 8.0f * density;
      gs.push_back(g);
    } else {
      gs.push_back(clamped_gaussian(c, radius, density));
    }
  }
  return gs;
}

glm::vec3 texel_centre(const ShadowVolume& map, int i, int j, int k) {
  const glm::vec3 t((i + 0.5f) / map.size.x, (j + 0.5f) / map.size.y, (k + 0.5f) / map.size.z);
  return glm::vec3(glm::inverse(map.world_to_texture) * glm::vec4(t, 1.0f));
}

class OpacityShadowMapOf : public ::testing::TestWithParam<Other> {};

TEST_P(OpacityShadowMapOf, HoldsTheExactDepthAtEveryTexelCentre) {
  const std::vector<ShadowCaster> gs = cloud(150, GetParam());
  const glm::dvec3 travel(-0.5, -1.0, -0.35);
  ShadowVolume map;
  build_opacity_shadow_map(gs, travel, {40, 24}, map);
  ASSERT_FALSE(map.empty());
  EXPECT_EQ(map.size.z, 24);
  const ShadowRayIndex exact(gs, travel);
  double largest = 0.0;
  for (int k = 0; k < map.size.z; k += 3)
    for (int j = 0; j < map.size.y; j += 2)
      for (int i = 0; i < map.size.x; i += 2) {
        const glm::vec3 p = texel_centre(map, i, j, k);
        const double want = exact.optical_depth_to_light(glm::dvec3(p));
        const float stored = map.optical_depth[(size_t(k) * map.size.y + j) * map.size.x + i];
        ASSERT_NEAR(stored, want, 2e-5 * (1.0 + want)) << i << " " << j << " " << k;
        EXPECT_NEAR(sample_optical_depth(map, p), stored, 2e-5 * (1.0 + want));
        largest = std::max(largest, want);
      }
  EXPECT_GT(largest, 1.0);
}

TEST_P(OpacityShadowMapOf, ReadsNothingBesideTheMediaAndTheWholeColumnBeyond) {
  const std::vector<ShadowCaster> gs = cloud(150, GetParam());
  const glm::dvec3 down(0.0, -1.0, 0.0);
  ShadowVolume map;
  build_opacity_shadow_map(gs, down, {64, 32}, map);
  const ShadowRayIndex exact(gs, down);
  EXPECT_EQ(sample_optical_depth(map, {9.0f, 0.0f, 0.0f}), 0.0f);   // beside the media
  EXPECT_EQ(sample_optical_depth(map, {0.5f, 20.0f, 0.3f}), 0.0f);  // above them
  // On the ground: the whole column, at a texel column's centre exactly.
  const glm::vec3 below = texel_centre(map, 30, 30, map.size.z - 1);
  const glm::vec3 ground(below.x, -5.0f, below.z);
  EXPECT_NEAR(sample_optical_depth(map, ground), exact.optical_depth_to_light(glm::dvec3(ground)), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(GaussiansSpheresAndEllipsoids, OpacityShadowMapOf,
                         ::testing::Values(Other::none, Other::spheres, Other::ellipsoids),
                         [](const auto& info) {
                           return info.param == Other::none      ? "Gaussians"
                                  : info.param == Other::spheres ? "WithSpheres"
                                                                 : "WithEllipsoids";
                         });

TEST(OpacityShadowMap, NoParticlesMakeAnEmptyMapAndANewVersion) {
  ShadowVolume map;
  build_opacity_shadow_map(cloud(10), {0.0, -1.0, 0.0}, {16, 8}, map);
  const uint64_t before = map.version;
  build_opacity_shadow_map({}, {0.0, -1.0, 0.0}, {16, 8}, map);
  EXPECT_TRUE(map.empty());
  EXPECT_GT(map.version, before);
  EXPECT_EQ(sample_optical_depth(map, {0.0f, 0.0f, 0.0f}), 0.0f);
}

}  // namespace
}  // namespace pyro
