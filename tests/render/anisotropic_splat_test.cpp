// The GL anisotropic splats (systems/billboard_render/anisotropic_splat_renderer.h, read back by
// render_anisotropic_snapshot) against the exact CPU reference of the same particles
// (systems/runtime/reference/anisotropic_reference.h).
//
// Bounds. For one particle both evaluate the same closed form, the GL side in float with erf
// from Abramowitz & Stegun 7.1.26 (|error| <= 1.5e-7) into an RGBA32F target: what differs is
// float rounding of the ray and the whitened terms, relative ~1e-6 of tau, so a pixel may differ
// by ~1e-5 at most; the bounds (RMSE 1e-4, any pixel 2e-3) leave room for that and still fail on
// any real mistake (a pixel the quad misses, a swapped axis). For overlapping particles GL
// composites whole particles in order of their centres' distance, where the reference mixes them
// where they overlap: that is the renderer's one approximation, held to an RMSE of 0.005. Last,
// the depth test against opaque geometry at the centre's depth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/core/rng.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "systems/billboard_render/anisotropic_splat_renderer.h"
#include "systems/runtime/reference/anisotropic_reference.h"
#include "systems/runtime/scene_runtime/anisotropic_snapshot.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/random_anisotropic.h"

namespace pyro {
namespace {

struct Comparison {
  double rmse = 0.0;          // GL against the reference
  double max_abs = 0.0;       // the largest channel difference
  double signal = 0.0;        // the reference against the bare background: what there is to get wrong
};

Comparison compare(const std::vector<AnisotropicGaussian>& ps, const CameraDescription& cam, int w, int h) {
  const glm::vec3 background(0.55f, 0.65f, 0.8f);
  const RgbImage gl = render_anisotropic_snapshot(ps, cam, w, h, background);
  const CameraFrame frame = make_camera_frame(cam.position, cam.target, cam.up, cam.fov_y_deg, cam.near, cam.far, w, h);
  const RgbImage ref = render_anisotropic_reference(ps, frame, glm::dvec3(background));
  RgbImage bare = ref;
  for (std::size_t i = 0; i < bare.rgb.size(); ++i) bare.rgb[i] = background[int(i % 3)];
  Comparison c;
  c.rmse = image_rmse(gl, ref);
  c.signal = image_rmse(ref, bare);
  for (std::size_t i = 0; i < gl.rgb.size(); ++i)
    c.max_abs = std::max(c.max_abs, double(std::abs(gl.rgb[i] - ref.rgb[i])));
  return c;
}

CameraDescription camera_at(const glm::vec3& position, const glm::vec3& target, float near) {
  CameraDescription cam;
  cam.position = position;
  cam.target = target;
  cam.fov_y_deg = 40.0f;
  cam.near = near;
  cam.far = 50.0f;
  return cam;
}

TEST(AnisotropicSplat, OneRotatedElongatedGaussianMatchesTheReference) {
  AnisotropicGaussian g;
  g.centre = {0.3f, -0.2f, 0.1f};
  g.rotation = glm::angleAxis(0.8f, glm::normalize(glm::vec3(0.4f, 1.0f, 0.3f)));
  g.scale = {0.9f, 0.1f, 0.3f};
  g.extinction = 6.0f;
  g.color = {1.0f, 0.7f, 0.4f};
  const Comparison c = compare({g}, camera_at({0.6f, 0.7f, 3.2f}, {0.0f, 0.0f, 0.0f}, 0.5f), 128, 96);
  std::printf("one rotated elongated particle: rmse %.2e, max %.2e, signal %.3f\n", c.rmse, c.max_abs, c.signal);
  EXPECT_GT(c.signal, 0.05);
  EXPECT_LT(c.rmse, 1e-4);
  EXPECT_LT(c.max_abs, 2e-3);
}

TEST(AnisotropicSplat, SixtyOverlappingParticlesAreWithinTheBar) {
  Rng rng(2024);
  std::vector<AnisotropicGaussian> ps;
  for (int i = 0; i < 60; ++i) ps.push_back(test::random_anisotropic(rng, 1.2f, 0.06f, 0.35f, 0.5f, 4.0f));
  const Comparison c = compare(ps, camera_at({0.5f, 0.8f, 6.0f}, {0.0f, 0.0f, 0.0f}, 0.5f), 128, 128);
  std::printf("60 overlapping particles: rmse %.2e, max %.2e, signal %.3f\n", c.rmse, c.max_abs, c.signal);
  EXPECT_GT(c.signal, 0.05);
  EXPECT_LT(c.rmse, 0.005);
}

TEST(AnisotropicSplat, CameraInsideAParticleSeesItsDensityAhead) {
  // The eye at 1.2 standard deviations from the centre of a large flat particle, looking across
  // it: every pixel's ray starts inside, and what it sees depends on its direction.
  AnisotropicGaussian g;
  g.rotation = glm::angleAxis(0.5f, glm::normalize(glm::vec3(1.0f, 0.2f, 0.0f)));
  g.scale = {1.5f, 0.6f, 1.0f};
  g.extinction = 1.2f;
  g.color = {0.9f, 0.95f, 1.0f};
  const Comparison c = compare({g}, camera_at({0.3f, 0.2f, 1.0f}, {-0.5f, 0.0f, -2.0f}, 0.1f), 96, 96);
  std::printf("camera inside: rmse %.2e, max %.2e, signal %.3f\n", c.rmse, c.max_abs, c.signal);
  EXPECT_GT(c.signal, 0.05);
  EXPECT_LT(c.rmse, 1e-4);
  EXPECT_LT(c.max_abs, 2e-3);
}

TEST(AnisotropicSplat, ParticleCrossingTheNearPlaneIsWhole) {
  // The eye outside the ellipsoids, the near plane (at 1.0) through them: the parts before the
  // near plane still count, as in the reference, which integrates from the eye.
  AnisotropicGaussian g;
  g.centre = {0.2f, 0.0f, 3.6f};
  g.rotation = glm::angleAxis(-0.4f, glm::vec3(0.0f, 1.0f, 0.0f));
  g.scale = {0.5f, 0.25f, 0.4f};
  g.extinction = 4.0f;
  g.color = {1.0f, 0.5f, 0.2f};
  AnisotropicGaussian far = g;  // and a particle well beyond, seen through it
  far.centre = {-0.3f, 0.1f, 0.0f};
  far.scale = {0.6f, 0.6f, 0.3f};
  far.color = {0.2f, 0.4f, 1.0f};
  const Comparison c = compare({g, far}, camera_at({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, 1.0f), 96, 96);
  std::printf("near-plane crossing: rmse %.2e, max %.2e, signal %.3f\n", c.rmse, c.max_abs, c.signal);
  EXPECT_GT(c.signal, 0.05);
  EXPECT_LT(c.rmse, 1e-4);
  EXPECT_LT(c.max_abs, 2e-3);
}

TEST(AnisotropicSplat, ParticleReachingPastTheEyeIsWhole) {
  // Beside the eye (outside it), long along the view axis: it crosses the near plane and the eye
  // plane, so no screen rectangle bounds what it shows; it is drawn over the whole viewport.
  AnisotropicGaussian g;
  g.centre = {0.7f, -0.1f, 4.3f};
  g.rotation = glm::angleAxis(0.1f, glm::vec3(1.0f, 0.0f, 0.0f));
  g.scale = {0.15f, 0.4f, 0.7f};
  g.extinction = 6.0f;
  g.color = {0.3f, 0.9f, 0.3f};
  const Comparison c = compare({g}, camera_at({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, 1.0f), 96, 96);
  std::printf("reaching past the eye: rmse %.2e, max %.2e, signal %.3f\n", c.rmse, c.max_abs, c.signal);
  EXPECT_GT(c.signal, 0.05);
  EXPECT_LT(c.rmse, 1e-4);
  EXPECT_LT(c.max_abs, 2e-3);
}

TEST(AnisotropicSplat, OpaqueDepthHidesParticlesWhoseCentreIsBehindIt) {
  // An opaque surface at the plane z = 0 (its window depth cleared into the target): the particle
  // centred in front of it (z = 1) is drawn whole, the one centred behind it (z = -1) not at all.
  shared_headless_context().make_current();
  const CameraFrame frame = make_camera_frame({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f},
                                              40.0f, 0.5f, 50.0f, 64, 64);
  AnisotropicGaussian front, behind;
  front.centre = {-0.8f, 0.0f, 1.0f};
  behind.centre = {0.8f, 0.0f, -1.0f};
  for (AnisotropicGaussian* g : {&front, &behind}) {
    g->scale = {0.25f, 0.25f, 0.5f};
    g->extinction = 8.0f;
  }
  const glm::vec4 plane = frame.view_projection * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  gpu::RenderTarget target(64, 64, GL_RGBA32F);
  target.bind();
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepth(0.5 * plane.z / plane.w + 0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glClearDepth(1.0);
  AnisotropicSplatRenderer renderer;
  renderer.upload({front, behind});
  renderer.draw(frame, target);
  const std::vector<float> rgba = target.read_rgba();
  const auto alpha_at = [&](const glm::vec3& p) {
    const glm::vec2 px = project_to_pixels(frame, p);
    return rgba[4 * (std::size_t(px.y) * 64 + std::size_t(px.x)) + 3];
  };
  EXPECT_GT(alpha_at(front.centre), 0.9f);
  EXPECT_EQ(alpha_at(behind.centre), 0.0f);
}

}  // namespace
}  // namespace pyro
