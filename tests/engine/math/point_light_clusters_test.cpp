// The few point lights clustered from many emitters (engine/math/point_light_clusters.h): they
// conserve the total intensity exactly, stand for each emitter alone when there are enough, and
// far from the emitters light a point as the emitters do; near them, more lights come closer.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "engine/core/rng.h"
#include "engine/math/point_light_clusters.h"

namespace pyro {
namespace {

std::vector<PointEmitter> fireball(int n) {
  Rng rng(3);
  std::vector<PointEmitter> e;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 p(rng.uniform(-1.5f, 1.5f), rng.uniform(0.5f, 3.0f), rng.uniform(-1.5f, 1.5f));
    const double t = rng.uniform(0.2f, 1.0f);
    e.push_back({p, glm::dvec3(1.0, 0.6, 0.2) * t, rng.uniform(0.3f, 0.7f)});
  }
  return e;
}

double relative_error(const glm::dvec3& got, const glm::dvec3& want) {
  return glm::length(got - want) / glm::length(want);
}

TEST(PointLightClusters, ConserveTheTotalIntensity) {
  const std::vector<PointEmitter> e = fireball(135);
  glm::dvec3 total(0.0);
  for (const PointEmitter& p : e) total += p.intensity;
  for (int count : {1, 2, 4, 8}) {
    const std::vector<PointEmitter> lights = cluster_point_lights(e, count);
    ASSERT_EQ(lights.size(), size_t(count));
    glm::dvec3 sum(0.0);
    for (const PointEmitter& l : lights) sum += l.intensity;
    EXPECT_LT(relative_error(sum, total), 1e-12) << count;
  }
}

TEST(PointLightClusters, EnoughLightsAreTheEmittersThemselves) {
  std::vector<PointEmitter> e = fireball(5);
  e.push_back({{9.0, 9.0, 9.0}, glm::dvec3(0.0), 1.0});  // dark: no light
  const std::vector<PointEmitter> lights = cluster_point_lights(e, 8);
  ASSERT_EQ(lights.size(), 5u);
  for (size_t i = 0; i < 5; ++i) EXPECT_EQ(lights[i].position, e[i].position);
  EXPECT_TRUE(cluster_point_lights(e, 0).empty());
  EXPECT_TRUE(cluster_point_lights({}, 4).empty());
}

TEST(PointLightClusters, FarAwayTheyLightAsTheEmittersAndNearMoreComeCloser) {
  const std::vector<PointEmitter> e = fireball(135);
  auto worst_error = [&](const std::vector<PointEmitter>& lights, double distance) {
    double worst = 0.0;
    for (int k = 0; k < 24; ++k) {
      const double a = 2.0 * 3.14159265358979 * k / 24.0;
      const glm::dvec3 x(distance * std::cos(a), 1.0, distance * std::sin(a));
      worst = std::max(worst, relative_error(point_irradiance(lights, x), point_irradiance(e, x)));
    }
    return worst;
  };
  const std::vector<PointEmitter> one = cluster_point_lights(e, 1), four = cluster_point_lights(e, 4),
                                   eight = cluster_point_lights(e, 8);
  EXPECT_LT(worst_error(one, 40.0), 0.01);  // far away: one light is the whole fire
  EXPECT_LT(worst_error(four, 40.0), 0.01);
  std::printf("at 3: 1 light %.3f, 4 lights %.3f, 8 lights %.3f\n", worst_error(one, 3.0),
              worst_error(four, 3.0), worst_error(eight, 3.0));
  EXPECT_LT(worst_error(four, 3.0), worst_error(one, 3.0));
  EXPECT_LT(worst_error(eight, 3.0), 0.1);
}

}  // namespace
}  // namespace pyro
