// The per-cell depth range of the particles (systems/composite/particle_depth_grid.h) against
// brute force: every pixel a sphere's image covers lies in a cell whose range holds the sphere's
// depths, cells no sphere reaches are empty, and a sphere reaching behind the eye widens all.
#include "systems/composite/particle_depth_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "engine/core/rng.h"
#include "engine/math/camera_math.h"

namespace pyro {
namespace {

const glm::ivec2 view{200, 120};

CameraFrame camera() {
  return make_camera_frame({0.0f, 1.0f, 6.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 50.0f, 0.1f,
                           100.0f, view.x, view.y);
}

// Does the ray through window pixel centre p hit the sphere?
bool covers(const CameraFrame& cam, glm::vec2 p, const glm::vec4& sphere) {
  const glm::vec2 ndc = p / glm::vec2(view) * 2.0f - 1.0f;
  const glm::vec3 dir =
      glm::normalize(glm::vec3(ndc.x / cam.projection[0][0], ndc.y / cam.projection[1][1], -1.0f));
  const glm::vec3 c = glm::vec3(cam.view * glm::vec4(glm::vec3(sphere), 1.0f));
  const float along = glm::dot(c, dir);
  return along > 0.0f && glm::dot(c, c) - along * along < sphere.w * sphere.w;
}

TEST(ParticleDepthGrid, EveryCoveredPixelsCellHoldsTheSphere) {
  const CameraFrame cam = camera();
  Rng rng(11);
  DrawList list;
  for (int k = 0; k < 12; ++k)
    list.center_radius.push_back({rng.uniform(-3.0f, 3.0f), rng.uniform(-0.5f, 2.5f),
                                  rng.uniform(-4.0f, 2.0f), rng.uniform(0.2f, 0.8f)});
  const ParticleDepthGrid g = particle_depth_grid(list, cam, view, 0.0f);
  ASSERT_EQ(g.cells, glm::ivec2(25, 15));
  for (const glm::vec4& s : list.center_radius) {
    const float d = view_depth(cam, glm::vec3(s));
    for (int y = 0; y < view.y; ++y)
      for (int x = 0; x < view.x; ++x) {
        if (!covers(cam, glm::vec2(x, y) + 0.5f, s)) continue;
        const size_t cell = static_cast<size_t>(y / 8) * g.cells.x + x / 8;
        EXPECT_LE(g.ranges[cell].near, d - s.w + 1e-4f) << x << " " << y;
        EXPECT_GE(g.ranges[cell].far, d + s.w - 1e-4f) << x << " " << y;
      }
  }
  // The cells no sphere's rectangle meets stay empty.
  int empty = 0;
  for (const ParticleDepthRange& r : g.ranges) empty += r.empty();
  EXPECT_GT(empty, 0);
}

TEST(ParticleDepthGrid, ReachWidensByPixels) {
  const CameraFrame cam = camera();
  DrawList list;
  list.center_radius.push_back({0.0f, 1.0f, 0.0f, 0.05f});  // a few pixels at the view's centre
  const ParticleDepthGrid tight = particle_depth_grid(list, cam, view, 0.0f);
  const ParticleDepthGrid wide = particle_depth_grid(list, cam, view, 17.0f);
  int a = 0, b = 0;
  for (const ParticleDepthRange& r : tight.ranges) a += !r.empty();
  for (const ParticleDepthRange& r : wide.ranges) b += !r.empty();
  EXPECT_GE(a, 1);
  EXPECT_LE(a, 4);
  // 17 pixels more on every side reach at least two cells further each way.
  EXPECT_GE(b, 25);
}

TEST(ParticleDepthGrid, ASphereAroundTheEyeWidensEveryCellOneBehindItNone) {
  const CameraFrame cam = camera();
  DrawList around, behind;
  around.center_radius.push_back({0.0f, 1.0f, 6.2f, 0.5f});
  behind.center_radius.push_back({0.0f, 1.0f, 9.0f, 0.5f});
  for (const ParticleDepthRange& r : particle_depth_grid(around, cam, view, 0.0f).ranges) {
    EXPECT_FALSE(r.empty());
    EXPECT_NEAR(r.far, 0.3f, 1e-3f);
  }
  for (const ParticleDepthRange& r : particle_depth_grid(behind, cam, view, 0.0f).ranges)
    EXPECT_TRUE(r.empty());
}

}  // namespace
}  // namespace pyro
