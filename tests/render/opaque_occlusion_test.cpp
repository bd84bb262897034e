// Particles and opaque geometry occlude each other: the camera looks straight down at a ground
// plane; a particle under the plane leaves the image untouched, one above it shows, and one
// cut by the plane shows only where its billboard is above the ground.
#include <gtest/gtest.h>

#include <cmath>

#include "components/frame_image.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

SceneDescription looking_down(float particle_y) {
  SceneDescription s;
  s.width = 64;
  s.height = 64;
  s.camera.position = {0.0f, 10.0f, 0.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.fov_y_deg = 30.0f;
  MeshDescription ground;
  ground.kind = MeshKind::ground_plane;
  ground.scale = 50.0f;
  ground.color = {0.2f, 0.2f, 0.2f};
  s.meshes.push_back(ground);
  if (!std::isnan(particle_y)) {
    CloudDescription c;
    c.count = 1;
    c.radius = 1.0f;
    c.density = 1.0f;
    c.color = {1.0f, 0.0f, 0.0f};
    c.box_min = {-1e-4f, particle_y - 1e-4f, -1e-4f};
    c.box_max = {1e-4f, particle_y + 1e-4f, 1e-4f};
    s.clouds.push_back(c);
  }
  return s;
}

std::vector<float> render_opaque_occlusion(float particle_y) {
  SceneRuntime r(looking_down(particle_y));
  r.step();
  return r.image().rgba;
}

double max_red_change(const std::vector<float>& a, const std::vector<float>& b) {
  double m = 0.0;
  for (size_t i = 0; i < a.size(); i += 4) m = std::max(m, static_cast<double>(std::abs(a[i] - b[i])));
  return m;
}

TEST(OpaqueOcclusion, GroundHidesParticlesBelowIt) {
  const auto ground_only = render_opaque_occlusion(NAN);
  EXPECT_EQ(max_red_change(render_opaque_occlusion(-0.5f), ground_only), 0.0) << "particle under the ground must be hidden";
  EXPECT_GT(max_red_change(render_opaque_occlusion(0.5f), ground_only), 0.5) << "particle above the ground must show";
}

}  // namespace
}  // namespace pyro
