// A flipbook fire is a light (systems/lighting/flipbook_fire_lights.h): each frame's mean linear
// radiance against texels of known colour, each billboard's intensity against s A L_f at the
// frame it shows, and in campfire.json the clustered lights carry exactly the billboards' total
// intensity, change as the frames play, and brighten the ground around the fires.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "components/fire_lights.h"
#include "components/frame_image.h"
#include "engine/math/color.h"
#include "engine/math/flipbook_sequence.h"
#include "systems/flipbook_fire/flipbook_emission.h"
#include "systems/flipbook_fire/flipbook_layout.h"
#include "systems/lighting/flipbook_fire_lights.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(FlipbookEmission, MeanLinearRadianceOfEachFrame) {
  FlipbookFrames frames;
  frames.width = 2;
  frames.height = 1;
  // Frame 0: two texels of sRGB 128 grey; frame 1: one white and one black texel, alpha 51.
  frames.rgba = {{128, 128, 128, 255, 128, 128, 128, 255}, {255, 255, 255, 51, 0, 0, 0, 51}};
  const FlipbookEmission one = flipbook_emission(frames, FlipbookBlend::one_minus_destination);
  ASSERT_EQ(one.frame_radiance.size(), 2u);
  EXPECT_NEAR(one.frame_radiance[0].x, srgb_to_linear(128.0f / 255.0f), 1e-6);
  EXPECT_NEAR(one.frame_radiance[1].y, 0.5, 1e-6);  // alpha ignored: black is transparent
  const FlipbookEmission alpha = flipbook_emission(frames, FlipbookBlend::linear_alpha);
  EXPECT_NEAR(alpha.frame_radiance[1].z, 0.5 * 0.2, 1e-6);
}

TEST(FlipbookFireLights, EachBillboardIsItsCardTimesItsFrame) {
  FlipbookFire fire;
  fire.position = {1.0f, 0.5f, -2.0f};
  fire.width = 0.4f;
  fire.aspect = 1.5f;
  fire.frames_per_second = 10.0f;
  fire.groups = {FlipbookGroup{}};  // the thesis' pairs: 3 rows x 2 columns
  fire.billboards = expand_flipbook_groups(fire);
  fire.frame_count = 4;
  FlipbookEmission emission;
  emission.frame_radiance = {{0.1f, 0.1f, 0.1f}, {0.2f, 0.1f, 0.0f}, {0.4f, 0.3f, 0.1f}, {0.8f, 0.5f, 0.2f}};
  const double seconds = 0.73;  // step 7
  const std::vector<PointEmitter> e = flipbook_fire_emitters(fire, emission, seconds);
  ASSERT_EQ(e.size(), fire.billboards.size());
  const double area = 0.4 * 0.6;
  // Every emitter puffs with the flame (engine/math/flame_flicker.h).
  const double flicker = flame_flicker(flicker_of(fire), seconds);
  EXPECT_GT(std::abs(flicker - 1.0), 1e-3);
  for (size_t k = 0; k < e.size(); ++k) {
    const FlipbookBillboard& b = fire.billboards[k];
    const int f = flipbook_frame(b.start_frame, b.increment, 7, 4);
    const glm::dvec3 want = glm::dvec3(emission.frame_radiance[size_t(f)]) * double(b.intensity) * area * flicker;
    EXPECT_LT(glm::length(e[k].intensity - want), 1e-6) << k;
    EXPECT_LT(glm::length(e[k].position - glm::dvec3(1.0, 0.8, -2.0)), 1e-6);  // half a card up
  }
  // A flipbook whose frame count does not match gives no light rather than a wrong frame.
  fire.frame_count = 5;
  EXPECT_TRUE(flipbook_fire_emitters(fire, emission, seconds).empty());
}

glm::dvec3 total(const std::vector<PointEmitter>& v) {
  glm::dvec3 s(0.0);
  for (const PointEmitter& e : v) s += e.intensity;
  return s;
}

double ground_mean(const FrameImage& img) {  // the lower third: ground in front of the fires
  double s = 0.0;
  size_t n = 0;
  for (int y = 2 * img.height / 3; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x, ++n) s += img.rgba[4 * (size_t(y) * img.width + x)];
  return s / double(n);
}

TEST(FlipbookFireLights, TheCampfireLightsTheGround) {
  SceneDescription scene = load_scene(test::scene_path("campfire.json"));
  scene.shadows = ShadowSettings{};
  RuntimeOptions o;
  o.readback = true;
  o.width_override = 96;
  o.height_override = 72;
  SceneRuntime lit(scene, o);
  lit.draw_frame(3);
  const FireLights& fire = lit.world().resource<const FireLights>();
  size_t billboards = 0;
  lit.world().each<const FlipbookFire>([&](const FlipbookFire& f) { billboards += f.billboards.size(); });
  ASSERT_EQ(fire.emitters.size(), billboards);
  ASSERT_FALSE(fire.lights.empty());
  ASSERT_LE(fire.lights.size(), 2u);  // "fire_lights": 2
  EXPECT_LT(glm::length(total(fire.lights) - total(fire.emitters)), 1e-9 * glm::length(total(fire.emitters)));
  const glm::dvec3 at3 = total(fire.emitters);
  const double lit_ground = ground_mean(lit.image());
  lit.draw_frame(9);
  EXPECT_GT(glm::length(total(lit.world().resource<const FireLights>().emitters) - at3), 1e-3 * glm::length(at3));

  scene.shadows->fire_lights = 0;
  SceneRuntime dark(scene, o);
  dark.draw_frame(3);
  EXPECT_TRUE(dark.world().resource<const FireLights>().lights.empty());
  EXPECT_GT(lit_ground, 1.25 * ground_mean(dark.image())) << lit_ground;
}

}  // namespace
}  // namespace pyro
