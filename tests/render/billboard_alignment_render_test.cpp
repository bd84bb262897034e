// Billboards facing the viewpoint against billboards facing the viewplane: identical for a
// particle on the view axis (the two orientations coincide there), different for a near
// particle far off axis (Johnson & McAllister 2005, section 3.1: the error grows towards the
// viewplane and away from the axis), and well defined for a particle at the eye itself.
#include <gtest/gtest.h>

#include <cmath>

#include "components/frame_image.h"
#include "systems/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

std::vector<float> render(const glm::vec3& at, BillboardAlignment alignment) {
  SceneDescription s;
  s.width = 120;
  s.height = 90;
  s.background = {0, 0, 0};
  s.camera.position = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.fov_y_deg = 60.0f;
  CloudDescription c;
  c.count = 1;
  c.radius = 0.5f;
  c.density = 1.0f;
  c.color = {1, 1, 1};
  c.box_min = at;
  c.box_max = at;
  s.clouds.push_back(c);
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

TEST(BillboardAlignmentRender, ParticleAtTheEyeStaysFinite) {
  for (BillboardAlignment a : {BillboardAlignment::viewplane, BillboardAlignment::viewpoint}) {
    const auto img = render({0.0f, 0.0f, 0.0f}, a);
    for (float v : img) ASSERT_TRUE(std::isfinite(v));
  }
}

}  // namespace
}  // namespace pyro
