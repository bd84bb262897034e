// Billboards facing the viewpoint against billboards facing the viewplane: identical for a
// particle on the view axis (the two orientations coincide there), different for a near
// particle far off axis (Johnson & McAllister 2005, section 3.1: the error grows towards the
// viewplane and away from the axis), and well defined for a particle at the eye itself.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "components/frame_image.h"
#include "engine/math/billboard_alignment.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/one_particle_scene.h"

namespace pyro {
namespace {

std::vector<float> render(const glm::vec3& at, BillboardAlignment alignment) {
  const SceneDescription s = test::one_particle_scene(at, 0.5f, 1.0f, 120, 90, 60.0f);
  RuntimeOptions o;
  o.alignment = alignment;
  SceneRuntime r(s, o);
  r.step();
  return r.image().rgba;
}

double max_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double m = 0;
  for (size_t i = 0; i < a.size(); ++i) m = std::max(m, static_cast<double>(std::abs(a[i] - b[i])));
  return m;
}

TEST(BillboardAlignmentRender, OnAxisBothModesAgree) {
  const glm::vec3 at{0.0f, 0.0f, -3.0f};
  EXPECT_LT(max_difference(render(at, BillboardAlignment::viewplane),
                           render(at, BillboardAlignment::viewpoint)), 2e-3);
}

TEST(BillboardAlignmentRender, NearAndOffAxisTheModesDiffer) {
  const glm::vec3 at{1.1f, 0.6f, -1.2f};
  EXPECT_GT(max_difference(render(at, BillboardAlignment::viewplane),
                           render(at, BillboardAlignment::viewpoint)), 0.05);
}

// Signed distance (pixels) from p to the convex quad a b c d (positive inside).
double inside_distance(const glm::dvec2& p, const std::array<glm::dvec2, 4>& q) {
  double d = 1e30;
  double area = 0;
  for (int i = 0; i < 4; ++i) area += q[i].x * q[(i + 1) % 4].y - q[(i + 1) % 4].x * q[i].y;
  const double orientation = area > 0 ? 1.0 : -1.0;
  for (int i = 0; i < 4; ++i) {
    const glm::dvec2 a = q[i], b = q[(i + 1) % 4];
    const glm::dvec2 e = b - a;
    const double cross = e.x * (p.y - a.y) - e.y * (p.x - a.x);
    d = std::min(d, orientation * cross / std::sqrt(e.x * e.x + e.y * e.y));
  }
  return d;
}

TEST(BillboardAlignmentRender, ShaderBuildsTheSameBillboardAsTheCppAxes) {
  // The GLSL copy of viewpoint_facing_axes: the rendered footprint covers exactly the quad the
  // C++ construction projects to (pixels more than a pixel inside are lit, more than a pixel
  // outside are not).
  const glm::vec3 at{1.1f, 0.6f, -1.2f};
  const auto img = render(at, BillboardAlignment::viewpoint);
  const CameraFrame f = make_camera_frame({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 0.1f, 200.0f, 120, 90);
  const BillboardAxes<double> axes = viewpoint_facing_axes<double>(
      glm::dvec3(at), glm::dvec3(0.0), glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0));
  std::array<glm::dvec2, 4> quad;
  const double r = 0.5;
  const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int k = 0; k < 4; ++k) {
    const glm::dvec3 p = glm::dvec3(at) + r * (corners[k][0] * axes.right + corners[k][1] * axes.up);
    const glm::vec2 px = project_to_pixels(f, glm::vec3(p));
    quad[k] = {px.x, px.y};
  }
  int lit_inside = 0;
  for (int y = 0; y < 90; ++y)
    for (int x = 0; x < 120; ++x) {
      const double d = inside_distance({x + 0.5, y + 0.5}, quad);
      const float v = img[(static_cast<size_t>(y) * 120 + x) * 4];
      if (d > 1.0) {
        EXPECT_GT(v, 0.0f) << x << "," << y;
        ++lit_inside;
      } else if (d < -1.0) {
        EXPECT_EQ(v, 0.0f) << x << "," << y;
      }
    }
  EXPECT_GT(lit_inside, 200);
}

TEST(BillboardAlignmentRender, ParticleAtTheEyeStaysFinite) {
  for (BillboardAlignment a : {BillboardAlignment::viewplane, BillboardAlignment::viewpoint}) {
    const auto img = render({0.0f, 0.0f, 0.0f}, a);
    ASSERT_EQ(img.size(), size_t(120 * 90 * 4));
    for (float v : img) ASSERT_TRUE(std::isfinite(v));
  }
}

}  // namespace
}  // namespace pyro
