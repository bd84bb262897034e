// Explosion shading and media layers (Umenhoffer et al. 2006, sections 3 and 4):
// - one dust particle's centre pixel against eq. 1 in closed form (alpha a C with
//   C = E P(mu) exp(-tau r) + ambient, P Cornette-Shanks from engine/math);
// - a particle layer at 1/8 resolution behind a thin opaque edge: with depth-aware upsampling
//   no particle light lands on opaque pixels more than 2 pixels from the edge, while bilinear
//   upsampling visibly does (the test can tell them apart).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "components/explosion_shading.h"
#include "components/frame_image.h"
#include "engine/math/phase_function.h"
#include "systems/composite/compositor.h"
#include "systems/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

SceneDescription dust_scene(const glm::vec3& at, float radius, float tau) {
  SceneDescription s;
  s.width = 96;
  s.height = 96;
  s.background = {0, 0, 0};
  s.camera.position = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.fov_y_deg = 50.0f;
  s.light.direction = {-0.6f, -0.8f, 0.0f};
  s.light.color = {1.0f, 1.0f, 1.0f};
  s.light.ambient = {0.1f, 0.1f, 0.1f};
  s.render.particles = ParticleShape::spherical;
  s.render.shading = ParticleShading::explosion;
  CloudDescription c;  // cloud particles are dust (medium 0), opacity 1
  c.count = 1;
  c.radius = radius;
  c.density = tau;
  c.box_min = c.box_max = at;
  s.clouds.push_back(c);
  return s;
}

TEST(ExplosionShading, DustCentrePixelFollowsEquationOne) {
  // The phase function's parameter g as the paper's (0) and either side: the shader's closed
  // form against engine/math's.
  for (float g : {0.0f, 0.6f, -0.5f}) {
    const float r = 0.6f, tau = 1.2f;
    const SceneDescription s = dust_scene({0, 0, -3}, r, tau);
    SceneRuntime run(s);
    ExplosionShading shading;
    for (MediumShading& m : shading.media) {
      m.detail_amplitude = 0.0f;
      m.g = g;
    }
    run.world().set_resource<ExplosionShading>(shading);
    run.step();
    const FrameImage& img = run.image();
    const int x = img.width / 2, y = img.height / 2;
    // The centre pixel's ray passes within half a pixel of the centre: d ~ 0, ds ~ 2r.
    const float alpha = 1.0f - std::exp(-tau * 2.0f * r);
    const glm::vec3 light = glm::normalize(s.light.direction);
    const double mu = glm::dot(light, glm::vec3(0, 0, 1));  // towards the eye: +z
    const double p = cornette_shanks(mu, g);
    // From the centre towards the light the chord is r.
    const double c = shading.light_irradiance * p * std::exp(-tau * r) + 0.1;
    const double expected = alpha * shading.media[0].albedo * c;
    const float* px = &img.rgba[4 * (static_cast<size_t>(y) * img.width + x)];
    EXPECT_NEAR(px[0], expected, 0.02 * expected) << g;
    EXPECT_NEAR(px[1], expected, 0.02 * expected) << g;
  }
}

// Returns the largest particle light on pixels of the opaque plane farther than `bound` pixels
// from any pixel where the plane is absent.
float halo(bool depth_aware, float bound) {
  // Looking down at a ground plane (blue, side 4) whose edge is at x = 2; a bright dust particle
  // below it, half under the plane, half beyond its edge.
  SceneDescription s = dust_scene({2.4f, -2.0f, 0.0f}, 1.6f, 3.0f);
  s.width = s.height = 128;
  s.camera.position = {0, 6, 0};
  s.camera.target = {0, 0, 0};
  s.camera.up = {0, 0, -1};
  s.light.direction = {0, -1, 0};
  s.render.layer_scale = 0.125f;
  MeshDescription g;
  g.kind = MeshKind::ground_plane;
  g.scale = 2.0f;  // half-size: the plane spans x, z in [-2, 2]
  g.color = {0, 0, 1};
  s.meshes.push_back(g);
  // Where the plane is: from the same view without the particle (the composited image cannot
  // tell: light bleeding onto the plane changes exactly the pixels in question).
  SceneDescription bare = s;
  bare.clouds.clear();
  SceneRuntime plane_run(bare);
  plane_run.step();
  const FrameImage& plane_img = plane_run.image();
  SceneRuntime run(s);
  MediaComposition m;
  m.depth_aware = depth_aware;
  run.world().set_resource<MediaComposition>(m);
  run.step();
  const FrameImage& img = run.image();
  const int w = img.width, h = img.height;
  auto at = [&](int x, int y, int c) { return img.rgba[4 * (static_cast<size_t>(y) * w + x) + c]; };
  std::vector<int> plane(static_cast<size_t>(w) * h);
  int plane_pixels = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      plane[y * w + x] = plane_img.rgba[4 * (static_cast<size_t>(y) * w + x) + 2] > 0.5f;
      plane_pixels += plane[y * w + x];
    }
  // The plane covers part of the view, not all of it, or there is no edge to test.
  EXPECT_GT(plane_pixels, w * h / 8);
  EXPECT_LT(plane_pixels, w * h * 7 / 8);
  float worst = 0.0f;
  const int b = static_cast<int>(std::ceil(bound));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!plane[y * w + x]) continue;
      bool near_edge = false;
      for (int dy = -b; dy <= b && !near_edge; ++dy)
        for (int dx = -b; dx <= b && !near_edge; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u >= 0 && v >= 0 && u < w && v < h && !plane[v * w + u]) near_edge = true;
        }
      if (!near_edge) worst = std::max(worst, at(x, y, 0));  // red: particle light only
    }
  return worst;
}

TEST(ExplosionLayers, DepthAwareUpsamplingLeavesNoHaloBeyondTwoPixels) {
  const float depth_aware = halo(true, 2.0f);
  const float bilinear = halo(false, 0.0f);  // any plane pixel
  EXPECT_LE(depth_aware, 1e-3f);
  // Plain upsampling bleeds particle light onto the plane (0.035 linear, about 0.2 in sRGB):
  // ten times the depth-aware bound, so the test tells the two apart.
  EXPECT_GT(bilinear, 0.01f);
}

}  // namespace
}  // namespace pyro
