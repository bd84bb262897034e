// The view frustum's planes against the closed form of a symmetric view, and against the
// projection itself for an off-axis stereo eye: what is culled projects outside the clip volume.
#include "engine/math/view_frustum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/mat4x4.hpp>

#include "engine/math/stereo_projection.h"

namespace pyro {
namespace {

TEST(ViewFrustum, SidePlanesOfASymmetricViewAreTheClosedForm) {
  // 90 degrees vertically, 2:1: inside where |y| <= depth and |x| <= 2 depth.
  const CameraFrame f = make_camera_frame({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90.0f, 0.5f, 50.0f, 200, 100);
  const ViewFrustum v = view_frustum(f);
  const float depth = 10.0f;
  EXPECT_FALSE(sphere_outside(v, {19.9f, 0, -depth}, 0.0f));
  EXPECT_TRUE(sphere_outside(v, {20.1f, 0, -depth}, 0.0f));
  EXPECT_FALSE(sphere_outside(v, {0, -9.9f, -depth}, 0.0f));
  EXPECT_TRUE(sphere_outside(v, {0, -10.1f, -depth}, 0.0f));
  // A sphere's distance to the right plane x = 2 depth: (x - 2 depth) / sqrt(5).
  const float x = 25.0f, distance = (x - 2.0f * depth) / std::sqrt(5.0f);
  EXPECT_TRUE(sphere_outside(v, {x, 0, -depth}, 0.99f * distance));
  EXPECT_FALSE(sphere_outside(v, {x, 0, -depth}, 1.01f * distance));
  // The far plane, and the eye's plane in place of the near one.
  EXPECT_TRUE(sphere_outside(v, {0, 0, -51.0f}, 0.9f));
  EXPECT_FALSE(sphere_outside(v, {0, 0, -51.0f}, 1.1f));
  EXPECT_FALSE(sphere_outside(v, {0, 0, -0.2f}, 0.0f));  // nearer than the near plane: kept
  EXPECT_TRUE(sphere_outside(v, {0, 0, 0.2f}, 0.1f));
  EXPECT_FALSE(sphere_outside(v, {0, 0, 0.2f}, 0.3f));
}

TEST(ViewFrustum, WhatAnOffAxisEyeCullsProjectsOutsideItsClipVolume) {
  const CameraFrame mono = make_camera_frame({1, 2, 3}, {0, 1, -5}, {0, 1, 0}, 50.0f, 0.1f, 40.0f, 320, 240);
  const CameraFrame eye = make_eye_frame(mono, StereoParameters{0.6f, 4.0f}, Eye::right);
  const ViewFrustum v = view_frustum(eye);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int culled = 0, kept = 0;
  for (int n = 0; n < 4000; ++n) {
    const glm::vec3 c = eye.eye + 30.0f * glm::vec3(u(rng), u(rng), u(rng));
    const float r = 0.5f + 2.0f * (u(rng) + 1.0f);
    const bool outside = sphere_outside(v, c, r);
    (outside ? culled : kept) += 1;
    // Points of the sphere: none of a culled one lies in the clip volume (in front of the eye).
    bool seen = false;
    for (int k = 0; k < 200; ++k) {
      glm::vec3 d(u(rng), u(rng), u(rng));
      if (glm::length(d) < 1e-3f) continue;
      const glm::vec4 q = eye.view_projection * glm::vec4(c + r * glm::normalize(d) * std::abs(u(rng)), 1.0f);
      seen = seen || (q.w > 0 && std::abs(q.x) <= q.w && std::abs(q.y) <= q.w && std::abs(q.z) <= q.w);
    }
    if (outside) {
      EXPECT_FALSE(seen) << n;
    }
    // A sphere whose centre projects inside is never culled.
    const glm::vec4 q = eye.view_projection * glm::vec4(c, 1.0f);
    if (q.w > 0 && std::abs(q.x) <= q.w && std::abs(q.y) <= q.w && std::abs(q.z) <= q.w) {
      EXPECT_FALSE(outside) << n;
    }
  }
  EXPECT_GT(culled, 1000);
  EXPECT_GT(kept, 200);
}

}  // namespace
}  // namespace pyro
