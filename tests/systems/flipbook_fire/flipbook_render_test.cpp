// Flipbook fire rendered end to end (Rose 2007, sections 4.3-4.6): the blends against their
// closed forms on one-billboard renders, the colour scaling with the overlap count, the stereo
// parallax of a billboard and of the campfire scene against the closed form of
// engine/math/stereo_projection.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/geometric.hpp>

#include "components/flipbook_draw_list.h"
#include "components/flipbook_fire.h"
#include "components/gpu_frame.h"
#include "components/view.h"
#include "engine/io/png_file.h"
#include "systems/runtime/scene/scene_loader.h"
#include "engine/math/color.h"
#include "engine/math/stereo_projection.h"
#include "systems/flipbook_fire/flipbook_geometry.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

constexpr int kW = 64, kH = 48;
constexpr float kBackground = 0.3f;

// A folder of `count` uniform frames of grey level `grey` (sRGB byte), RGB (alpha = grey).
std::string uniform_flipbook(const std::string& name, uint8_t grey, int count = 3) {
  const fs::path dir = test::scratch_dir(name);
  for (int f = 0; f < count; ++f)
    write_png((dir / ("frame_" + std::to_string(f) + ".png")).string(), 8, 8, 3,
              std::vector<uint8_t>(8 * 8 * 3, grey));
  return dir.string();
}

// One frame of a smooth round blob (grey 255 exp(-r^2 / (2 sigma^2)), sigma = 5 of 32 pixels):
// its image's centroid moves continuously with the billboard, not in whole pixels.
std::string blob_flipbook(const std::string& name) {
  const fs::path dir = test::scratch_dir(name);
  std::vector<uint8_t> px(32 * 32 * 3);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const double r2 = (x + 0.5 - 16) * (x + 0.5 - 16) + (y + 0.5 - 16) * (y + 0.5 - 16);
      const auto v = static_cast<uint8_t>(std::lround(255.0 * std::exp(-r2 / 50.0)));
      for (int c = 0; c < 3; ++c) px[static_cast<size_t>(y * 32 + x) * 3 + c] = v;
    }
  write_png((dir / "frame_0.png").string(), 32, 32, 3, px);
  return dir.string();
}

// One fire of `rows` billboards 1 x 1 straight ahead of a camera 2 units away.
SceneDescription billboard_scene(const std::string& flipbook, FlipbookBlend blend, int rows) {
  SceneDescription s;
  s.width = kW;
  s.height = kH;
  s.background = glm::vec3(kBackground);
  s.camera.position = {0.0f, 0.5f, 2.0f};
  s.camera.target = {0.0f, 0.5f, 0.0f};
  s.camera.fov_y_deg = 60.0f;
  FlipbookFire fire;
  fire.flipbook = flipbook;
  fire.width = 1.0f;
  fire.aspect = 1.0f;
  fire.blend = blend;
  fire.overlap_exponent = 1.0f;
  fire.flicker = 0.0f;  // steady: the blend's closed forms
  FlipbookGroup g;
  g.rows = rows;
  g.columns = 1;
  g.row_spacing = 0.05f;
  g.column_depths = {0.0f};
  fire.groups.push_back(g);
  s.fires.push_back(fire);
  return s;
}

glm::vec3 centre_pixel(SceneRuntime& r) {
  const std::vector<float> px = r.world().resource<GpuFrame>().eyes[0].scene->read_rgba();
  const size_t i = (static_cast<size_t>(kH / 2) * kW + kW / 2) * 4;
  return {px[i], px[i + 1], px[i + 2]};
}

TEST(FlipbookRender, OneMinusDestinationBlendIsSrcPlusDstMinusProduct) {
  const uint8_t grey = 150;
  RuntimeOptions o;
  o.readback = false;
  SceneRuntime r(billboard_scene(uniform_flipbook("screen", grey), FlipbookBlend::one_minus_destination, 1), o);
  r.step();
  const float s = srgb_to_linear(grey / 255.0f), d = kBackground;
  const glm::vec3 c = centre_pixel(r);
  // Rose 2007, section 4.3: S_r (1 - D_r) + D_r.
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], s + d - s * d, 2e-3f);
  // And not the linear blend, which differs by far more than the tolerance here.
  const float a = grey / 255.0f;
  EXPECT_GT(std::fabs((s + d - s * d) - (s * a + d * (1 - a))), 0.05f);
}

TEST(FlipbookRender, LinearAlphaBlend) {
  const uint8_t grey = 200;
  RuntimeOptions o;
  o.readback = false;
  SceneRuntime r(billboard_scene(uniform_flipbook("alpha", grey), FlipbookBlend::linear_alpha, 1), o);
  r.step();
  const float s = srgb_to_linear(grey / 255.0f), a = grey / 255.0f, d = kBackground;
  const glm::vec3 c = centre_pixel(r);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], s * a + d * (1 - a), 2e-3f);
}

TEST(FlipbookRender, OverlappingBillboardsAreScaledDown) {
  // Two billboards on one centre line: each at intensity 1 / 2 (exponent 1), blended twice:
  // 1 - (1 - d)(1 - s/2)^2.
  const uint8_t grey = 230;
  RuntimeOptions o;
  o.readback = false;
  SceneRuntime r(billboard_scene(uniform_flipbook("overlap", grey), FlipbookBlend::one_minus_destination, 2), o);
  r.step();
  const float s = srgb_to_linear(grey / 255.0f), d = kBackground;
  const float expected = 1.0f - (1.0f - d) * (1.0f - s / 2) * (1.0f - s / 2);
  const glm::vec3 c = centre_pixel(r);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], expected, 2e-3f);
  // Unscaled, the pair would be 1 - (1 - d)(1 - s)^2: far brighter.
  EXPECT_GT((1.0f - (1.0f - d) * (1.0f - s) * (1.0f - s)) - expected, 0.1f);
}

// Weighted centroid of (view - background) over columns [x0, x1) of one eye's scene target.
struct Centroid {
  double x = 0, y = 0, weight = 0;
};
Centroid centroid_flipbook_render(const std::vector<float>& px, const std::vector<float>& base, int w, int h, int x0, int x1) {
  Centroid c;
  for (int y = 0; y < h; ++y)
    for (int x = x0; x < x1; ++x) {
      const size_t i = (static_cast<size_t>(y) * w + x) * 4;
      const double v = std::max(0.0f, px[i] - base[i]) + std::max(0.0f, px[i + 1] - base[i + 1]);
      c.x += v * (x + 0.5);
      c.y += v * (y + 0.5);
      c.weight += v;
    }
  if (c.weight > 0) {
    c.x /= c.weight;
    c.y /= c.weight;
  }
  return c;
}

TEST(FlipbookRender, StereoParallaxOfABillboardIsTheClosedForm) {
  SceneDescription s = billboard_scene(blob_flipbook("stereo"), FlipbookBlend::one_minus_destination, 1);
  s.fires[0].width = 0.5f;
  s.camera.position = {0.0f, 0.375f, 2.0f};  // level with the billboard's centre
  s.camera.target = {0.0f, 0.375f, 0.0f};
  s.fires[0].aspect = 1.0f;
  s.fires[0].position = {0.0f, 0.125f, 0.0f};  // centre at the camera's height, 0.375
  RuntimeOptions o;
  o.readback = false;
  o.stereo_mode = StereoMode::side_by_side;
  o.interocular = 0.3f;
  o.zero_parallax_distance = 1.0f;
  SceneRuntime r(s, o);
  r.step();
  const GpuFrame& f = r.world().resource<GpuFrame>();
  const std::vector<float> base(static_cast<size_t>(kW) * kH * 4, kBackground);
  const Centroid l = centroid_flipbook_render(f.eyes[0].scene->read_rgba(), base, kW, kH, 0, kW);
  const Centroid rr = centroid_flipbook_render(f.eyes[1].scene->read_rgba(), base, kW, kH, 0, kW);
  ASSERT_GT(l.weight, 0.0);
  // The billboard faces the mid-eye and the camera looks level along -z: its plane is at view
  // depth 2 for both eyes (mono frame: the mid-eye), so all of it has the parallax of z = 2.
  const CameraFrame mono = r.world().resource<View>().frame;
  const double expected = horizontal_parallax_pixels(mono, {0.3f, 1.0f}, 2.0);
  EXPECT_GT(std::fabs(expected), 3.0);
  EXPECT_NEAR(rr.x - l.x, expected, 0.1);
  EXPECT_NEAR(rr.y - l.y, 0.0, 0.02);
}

TEST(FlipbookRender, OneDrawListFacingTheMidEyeServesBothEyes) {
  // A fire off to the side, the camera orbiting: each frame the group faces the mid-eye point
  // (the mono camera), not either eye, and the orientation is made once per frame.
  SceneDescription s = billboard_scene(uniform_flipbook("mid", 200), FlipbookBlend::one_minus_destination, 2);
  s.fires[0].position = {1.0f, 0.0f, -0.5f};
  s.camera.orbit_deg_per_second = 90.0f;
  RuntimeOptions o;
  o.readback = false;
  o.stereo_mode = StereoMode::left_right;
  o.interocular = 0.4f;
  SceneRuntime r(s, o);
  for (int f = 0; f < 3; ++f) {
    r.step();
    const View& view = r.world().resource<View>();
    const FlipbookDrawList& list = r.world().resource<FlipbookDrawList>();
    ASSERT_EQ(view.eyes.size(), 2u);
    EXPECT_EQ(list.viewer, view.frame.eye);
    EXPECT_NEAR(glm::length(0.5f * (view.eyes[0].eye + view.eyes[1].eye) - view.frame.eye), 0.0f, 1e-5f);
    ASSERT_EQ(list.fires.size(), 1u);
    glm::vec3 to_mid = view.frame.eye - s.fires[0].position;
    to_mid.y = 0.0f;
    EXPECT_NEAR(glm::dot(list.fires[0].frame.toward, glm::normalize(to_mid)), 1.0f, 1e-5f) << "frame " << f;
    for (const glm::vec3& eye : {view.eyes[0].eye, view.eyes[1].eye}) {
      glm::vec3 to_eye = eye - s.fires[0].position;
      to_eye.y = 0.0f;
      EXPECT_LT(glm::dot(list.fires[0].frame.toward, glm::normalize(to_eye)), 1.0f - 1e-4f);
    }
  }
  for (const auto& st : r.schedule().stats())
    if (st.name == "flipbook_orient" || st.name == "flipbook_render") {
      EXPECT_EQ(st.frames, 3u) << st.name;
    }
}

TEST(FlipbookRender, CampfireSideBySideHasTheParallaxOfItsBillboards) {
  // content/scenes/campfire.json with its default (baked) flipbook, in side-by-side stereo with
  // the zero-parallax plane moved to 1 so that the fire's parallax is many pixels. The fire's
  // measured parallax (centroid of its light, right eye minus left) must lie between the
  // closed-form parallaxes of its nearest and farthest billboard corners; the vertical parallax
  // must vanish.
  SceneDescription scene = load_scene(test::scene_path("campfire.json"));
  SceneDescription no_fire = scene;
  no_fire.fires.clear();
  RuntimeOptions o;
  o.readback = false;
  o.stereo_mode = StereoMode::side_by_side;
  o.width_override = 240;
  o.height_override = 180;
  o.zero_parallax_distance = 1.0f;
  SceneRuntime with(scene, o), without(no_fire, o);
  with.step();
  without.step();
  const int w = 240, h = 180;
  const View& view = with.world().resource<View>();
  const StereoParameters stereo{scene.camera.interocular, 1.0f};
  std::vector<FlipbookFire> fires;
  with.world().each<FlipbookFire>([&](FlipbookFire& f) { fires.push_back(f); });
  ASSERT_EQ(fires.size(), 1u);
  const FlipbookFire& fire = fires[0];
  const GpuFrame& a = with.world().resource<GpuFrame>();
  const GpuFrame& b = without.world().resource<GpuFrame>();
  const Centroid l = centroid_flipbook_render(a.eyes[0].scene->read_rgba(), b.eyes[0].scene->read_rgba(), w, h, 0, w);
  const Centroid r = centroid_flipbook_render(a.eyes[1].scene->read_rgba(), b.eyes[1].scene->read_rgba(), w, h, 0, w);
  ASSERT_GT(l.weight, 1.0) << "the fire is visible in the left eye";
  ASSERT_GT(r.weight, 1.0) << "the fire is visible in the right eye";
  const FireFrame frame = face_viewer(fire.position, fire.up, view.frame.eye, -view.frame.forward);
  double z_min = 1e9, z_max = 0;
  for (const FlipbookQuad& q : flipbook_quads(fire, frame, 0, fire.frame_count))
    for (const glm::vec3& c : q.corners) {
      z_min = std::min<double>(z_min, view_depth(view.frame, c));
      z_max = std::max<double>(z_max, view_depth(view.frame, c));
    }
  const double p_near = horizontal_parallax_pixels(view.frame, stereo, z_min);
  const double p_far = horizontal_parallax_pixels(view.frame, stereo, z_max);
  const double measured = r.x - l.x;
  EXPECT_GT(measured, p_near - 0.25);
  EXPECT_LT(measured, p_far + 0.25);
  EXPECT_GT(p_near, 5.0);
  EXPECT_NEAR(r.y - l.y, 0.0, 0.35);
}

}  // namespace
}  // namespace pyro
