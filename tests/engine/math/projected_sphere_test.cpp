// engine/math/projected_sphere.h against brute force: the rectangle of many points of the
// sphere's surface, projected, for spheres about the view and off-axis frustums (a stereo eye's).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/math/projected_sphere.h"

namespace pyro {
namespace {

// The rectangle of `n` x `n` points on the surface (longitude, latitude), projected.
ScreenRect sampled_rect(const glm::vec3& c, float r, const glm::mat4& projection, glm::vec2 viewport,
                        int n) {
  ScreenRect s{glm::vec2(1e30f), glm::vec2(-1e30f)};
  const double pi = std::numbers::pi;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double phi = 2.0 * pi * i / n, theta = pi * j / n;
      const glm::vec3 p = c + r * glm::vec3(std::sin(theta) * std::cos(phi),
                                            std::sin(theta) * std::sin(phi), std::cos(theta));
      const glm::vec4 q = projection * glm::vec4(p, 1.0f);
      const glm::vec2 px = (glm::vec2(q) / q.w * 0.5f + 0.5f) * viewport;
      s.lo = glm::min(s.lo, px);
      s.hi = glm::max(s.hi, px);
    }
  }
  return s;
}

TEST(ProjectedSphere, RectangleBoundsTheImageTightly) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uni(-1.0f, 1.0f);
  const glm::vec2 viewport(640.0f, 480.0f);
  const glm::mat4 projections[] = {
      glm::perspective(glm::radians(50.0f), 640.0f / 480.0f, 0.1f, 100.0f),
      glm::frustum(-0.06f, 0.09f, -0.05f, 0.05f, 0.1f, 100.0f),  // off-axis, as a stereo eye
  };
  for (const glm::mat4& projection : projections) {
    for (int k = 0; k < 100; ++k) {
      const float depth = 2.0f + 10.0f * (uni(rng) + 1.0f);
      const glm::vec3 c(uni(rng) * depth * 0.6f, uni(rng) * depth * 0.5f, -depth);
      const float r = (0.05f + 0.9f * (uni(rng) + 1.0f) / 2.0f) * std::min(depth - 0.2f, 3.0f);
      ScreenRect exact;
      ASSERT_TRUE(projected_sphere_rect(c, r, projection, viewport, exact));
      const ScreenRect sampled = sampled_rect(c, r, projection, viewport, 360);
      // Every sampled point inside; the sides touched to within the sampling's spacing.
      const float slack = 0.02f + 2e-3f * glm::max(exact.size().x, exact.size().y);
      for (int a = 0; a < 2; ++a) {
        EXPECT_LE(exact.lo[a], sampled.lo[a] + 1e-3f) << k;
        EXPECT_GE(exact.hi[a], sampled.hi[a] - 1e-3f) << k;
        EXPECT_NEAR(exact.lo[a], sampled.lo[a], slack) << k;
        EXPECT_NEAR(exact.hi[a], sampled.hi[a], slack) << k;
      }
    }
  }
}

TEST(ProjectedSphere, CentredSphereClosedForm) {
  // On the axis the image is a disc of radius f tan(asin(r / D)) in NDC units, f = P[1][1].
  const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
  const float D = 5.0f, r = 1.5f;
  ScreenRect s;
  ASSERT_TRUE(projected_sphere_rect({0.0f, 0.0f, -D}, r, projection, {200.0f, 200.0f}, s));
  const float half = projection[1][1] * std::tan(std::asin(r / D)) * 100.0f;
  EXPECT_NEAR(s.lo.x, 100.0f - half, 1e-3f);
  EXPECT_NEAR(s.hi.y, 100.0f + half, 1e-3f);
}

TEST(ProjectedSphere, NoRectangleForASphereReachingTheEyePlane) {
  const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
  ScreenRect s;
  EXPECT_FALSE(projected_sphere_rect({0.0f, 0.0f, -1.0f}, 1.0f, projection, {100.0f, 100.0f}, s));
  EXPECT_FALSE(projected_sphere_rect({0.0f, 0.0f, 2.0f}, 1.0f, projection, {100.0f, 100.0f}, s));
  EXPECT_FALSE(projected_sphere_rect({0.0f, 0.0f, -2.0f}, 0.0f, projection, {100.0f, 100.0f}, s));
}

}  // namespace
}  // namespace pyro
