// A fire light at zero distance from the point it lights, and points inside its emitters: the
// point-source law I / d^2 is infinite at d = 0; the engine holds each emitter's irradiance below
// I / r^2 inside its radius r (engine/math/point_light_clusters.h). The clustered lights keep that
// bound: a cluster of summed intensity sum I_i and size R^2 = the intensity-weighted mean of
// (d_i^2 + r_i^2) about its centroid lights no point brighter than sum I_i / R^2, which by
// Cauchy-Schwarz is at most sum I_i / r_i^2, the emitters' own bound. A cluster sized by its
// emitters' spread alone (the naive k-means radius) has R = 0 when they coincide: infinite at its
// centre.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/core/rng.h"
#include "engine/math/point_light_clusters.h"

namespace pyro {
namespace {

TEST(StabilityFireLight, AtZeroDistanceAndInsideItsRadiusAnEmitterGivesIOverRSquared) {
  const PointEmitter e{{1.0, 2.0, 3.0}, {4.0, 2.0, 1.0}, 0.25};
  const glm::dvec3 cap = e.intensity / (e.radius * e.radius);
  for (double d : {0.0, 1e-300, 1e-12, 0.1, 0.25}) {
    const glm::dvec3 got = point_irradiance({e}, e.position + glm::dvec3(0.0, d, 0.0));
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(got[c], cap[c]) << "d = " << d;
  }
  const glm::dvec3 outside = point_irradiance({e}, e.position + glm::dvec3(0.5, 0.0, 0.0));
  for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(outside[c], e.intensity[c] / 0.25);
}

// Emitters piled on one point, alone and among scattered ones, clustered into fewer lights: at
// every emitter, at every light's centre and on a grid through them, the lights' irradiance is
// finite and no more than the sum of the emitters' own caps I / r^2.
TEST(StabilityFireLight, ClusteredLightsNeverExceedTheirEmittersCaps) {
  Rng rng(11);
  std::vector<PointEmitter> pile, mixed;
  for (int i = 0; i < 6; ++i) pile.push_back({{0.0, 1.0, 0.0}, {1.0 + i, 0.5, 0.2}, 0.05 + 0.01 * i});
  mixed = pile;
  for (int i = 0; i < 40; ++i)
    mixed.push_back({{rng.uniform(-1.0f, 1.0f), rng.uniform(0.0f, 2.0f), rng.uniform(-1.0f, 1.0f)},
                     {rng.uniform(0.1f, 3.0f), rng.uniform(0.1f, 2.0f), rng.uniform(0.0f, 1.0f)},
                     rng.uniform(0.02f, 0.2f)});
  for (const std::vector<PointEmitter>* emitters : {&pile, &mixed}) {
    glm::dvec3 caps(0.0);
    for (const PointEmitter& e : *emitters) caps += e.intensity / (e.radius * e.radius);
    for (int count : {1, 2, 4, 8}) {
      const std::vector<PointEmitter> lights = cluster_point_lights(*emitters, count);
      std::vector<glm::dvec3> points;
      for (const PointEmitter& e : *emitters) points.push_back(e.position);
      for (const PointEmitter& l : lights) points.push_back(l.position);
      for (int i = -4; i <= 4; ++i)
        for (int j = 0; j <= 8; ++j) points.push_back({0.25 * i, 0.25 * j, 0.0});
      for (const glm::dvec3& x : points) {
        const glm::dvec3 e = point_irradiance(lights, x);
        for (int c = 0; c < 3; ++c) {
          ASSERT_TRUE(std::isfinite(e[c])) << emitters->size() << " emitters, " << count << " lights";
          ASSERT_LE(e[c], caps[c] * (1.0 + 1e-12)) << emitters->size() << " emitters, " << count << " lights";
        }
      }
    }
  }
}

}  // namespace
}  // namespace pyro
