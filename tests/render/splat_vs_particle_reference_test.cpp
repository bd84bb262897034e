// The GL splat image of a small particle set against the exact particle reference
// (systems/runtime/reference/particle_reference.h: closed-form erf integrals of the same Gaussians): the
// image RMSE, linear colour in [0, 1], must stay within the project's accuracy bar (0.03).
// Differences come from compositing whole splats in depth order where overlapping Gaussians
// really mix, and from the 8-bit-free but bilinearly sampled footprint table.
#include <gtest/gtest.h>

#include "systems/runtime/cloud_import/scene_volume.h"

#include <cmath>
#include <vector>

#include "engine/core/rng.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/reference/particle_reference.h"
#include "tools/import/particle_snapshot.h"

namespace pyro {
namespace {

double splat_rmse(const std::vector<GaussianParticle>& ps, int size) {
  CameraDescription cam;
  cam.position = {0.5f, 0.8f, 7.0f};
  cam.target = {0.0f, 0.0f, 0.0f};
  cam.fov_y_deg = 40.0f;
  cam.near = 1.0f;
  cam.far = 20.0f;
  const glm::vec3 background(0.55f, 0.65f, 0.8f);
  const RgbImage splat = render_particle_snapshot(ps, cam, size, size, background);
  const ParticlePool pool = to_particle_pool(ps);
  const CameraFrame frame =
      make_camera_frame(cam.position, cam.target, cam.up, cam.fov_y_deg, cam.near, cam.far, size, size);
  const RgbImage ref = render_particles_reference(pool, frame, glm::dvec3(background));
  return image_rmse(ref, splat);
}

TEST(SplatVsParticleReference, OneParticleIsNearlyExact) {
  const double rmse = splat_rmse({{0.0f, 0.0f, 0.0f, 1.2f, 0.6f, 1.0f, 0.95f, 0.9f}}, 96);
  std::printf("one particle: rmse %.5f\n", rmse);
  EXPECT_LT(rmse, 0.01);  // measured 0.0053: the cube-clamped kernel seen obliquely
}

TEST(SplatVsParticleReference, ASmallOverlappingSetIsWithinTheBar) {
  Rng rng(2024);
  std::vector<GaussianParticle> ps;
  for (int i = 0; i < 60; ++i) {
    GaussianParticle p;
    p.x = rng.uniform(-1.5f, 1.5f);
    p.y = rng.uniform(-0.8f, 0.8f);
    p.z = rng.uniform(-1.0f, 1.0f);
    p.radius = rng.uniform(0.3f, 0.8f);
    p.density = rng.uniform(0.1f, 0.5f);
    const float lit = 0.6f + 0.4f * (p.y + 0.8f) / 1.6f;  // brighter on top, like an imported cloud
    p.r = lit;
    p.g = 0.97f * lit;
    p.b = 0.93f * lit;
    ps.push_back(p);
  }
  const double rmse = splat_rmse(ps, 128);
  std::printf("60 particles: rmse %.5f\n", rmse);
  EXPECT_LT(rmse, 0.01);  // measured 0.0040; the project bar is 0.03
  EXPECT_GT(rmse, 0.0);  // two different renderers: never identical
}

}  // namespace
}  // namespace pyro
