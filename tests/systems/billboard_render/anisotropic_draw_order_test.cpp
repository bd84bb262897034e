// The anisotropic pass's draw order (systems/billboard_render/anisotropic_splat_renderer.h):
// farthest centre first, equal distances in ascending index, whatever the input order.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "engine/core/rng.h"
#include "systems/billboard_render/anisotropic_splat_renderer.h"

namespace pyro {
namespace {

TEST(AnisotropicDrawOrder, FarthestFirstAndTiesByIndex) {
  const glm::vec3 eye(0.0f, 0.0f, 5.0f);
  // Indices 1, 3 and 4 lie at distance 5 (ties); 0 at 6; 2 at 1.
  const std::vector<glm::vec3> centres = {{0, 0, -1}, {0, 0, 0}, {0, 0, 4}, {3, 4, 5}, {0, 5, 5}};
  EXPECT_EQ(back_to_front_order(centres, eye), (std::vector<uint32_t>{0, 1, 3, 4, 2}));
}

TEST(AnisotropicDrawOrder, ManyParticlesAreSortedByDistance) {
  Rng rng(4);
  std::vector<glm::vec3> centres(20000);
  for (glm::vec3& c : centres) c = {rng.uniform(-2, 2), float(int(rng.uniform(0, 4))), rng.uniform(-2, 2)};
  const glm::vec3 eye(0.5f, 1.0f, 3.0f);
  const std::vector<uint32_t> order = back_to_front_order(centres, eye);
  ASSERT_EQ(order.size(), centres.size());
  std::vector<int> seen(centres.size(), 0);
  for (std::size_t k = 0; k < order.size(); ++k) {
    ++seen[order[k]];
    if (k == 0) continue;
    const glm::dvec3 a = glm::dvec3(centres[order[k - 1]]) - glm::dvec3(eye);
    const glm::dvec3 b = glm::dvec3(centres[order[k]]) - glm::dvec3(eye);
    const double da = glm::dot(a, a), db = glm::dot(b, b);
    ASSERT_TRUE(da > db || (da == db && order[k - 1] < order[k])) << k;
  }
  for (int s : seen) EXPECT_EQ(s, 1);
}

}  // namespace
}  // namespace pyro
