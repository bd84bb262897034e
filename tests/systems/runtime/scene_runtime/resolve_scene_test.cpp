// The runtime's first layer alone: options merged over the scene's choices, a quality pick
// applied (and overridden by an explicit option), the budget refused from plain data, with no
// OpenGL context, no file and no world.
#include <gtest/gtest.h>

#include <string>

#include "engine/core/user_error.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/resolve_scene.h"

namespace pyro {
namespace {

SceneDescription cloud_scene(const std::string& extra = "") {
  return parse_scene(R"({"output": {"width": 320, "height": 200, "fps": 24},
      "camera": {"stereo": {"interocular": 0.1, "zero_parallax_distance": 5, "eye_order": "left-right"}},
      "render": {"billboards": "viewplane", "layer_scale": 0.5},
      "clouds": [{"count": 1000}, {"count": 500}])" + extra + "}",
                     "test.json");
}

std::string refusal_resolve_scene(const SceneDescription& scene, const RuntimeOptions& options, int max_texture) {
  try {
    resolve_scene(scene, options, max_texture);
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

TEST(ResolveScene, KeepsTheScenesChoicesWithoutOptions) {
  const ResolvedScene r = resolve_scene(cloud_scene(), RuntimeOptions{}, 4096);
  EXPECT_EQ(r.settings.width, 320);
  EXPECT_EQ(r.settings.height, 200);
  EXPECT_EQ(r.settings.alignment, BillboardAlignment::viewplane);
  EXPECT_FLOAT_EQ(r.settings.layer_scale, 0.5f);
  EXPECT_FLOAT_EQ(r.stereo.parameters.interocular, 0.1f);
  EXPECT_FLOAT_EQ(r.stereo.parameters.zero_parallax_distance, 5.0f);
  EXPECT_EQ(r.stereo.eye_order, EyeOrder::left_right);
  EXPECT_FLOAT_EQ(r.clock.dt, 1.0f / 24.0f);
  EXPECT_EQ(r.substeps, 1);
  EXPECT_EQ(r.views, 1);
  EXPECT_EQ(r.output_width, 320);
}

TEST(ResolveScene, OptionsReplaceTheScenesChoices) {
  RuntimeOptions o;
  o.width_override = 100;
  o.alignment = BillboardAlignment::viewpoint;
  o.layer_scale = 0.25f;
  o.swap_eyes = true;
  o.interocular = 0.3f;
  o.stereo_mode = StereoMode::side_by_side;
  const ResolvedScene r = resolve_scene(cloud_scene(), o, 4096);
  EXPECT_EQ(r.settings.width, 100);
  EXPECT_EQ(r.settings.height, 200);  // not overridden
  EXPECT_EQ(r.settings.alignment, BillboardAlignment::viewpoint);
  EXPECT_FLOAT_EQ(r.settings.layer_scale, 0.25f);
  EXPECT_EQ(r.stereo.eye_order, EyeOrder::right_left);
  EXPECT_FLOAT_EQ(r.stereo.parameters.interocular, 0.3f);
  EXPECT_FLOAT_EQ(r.stereo.parameters.zero_parallax_distance, 5.0f);  // not overridden
  EXPECT_EQ(r.views, 2);
  EXPECT_EQ(r.output_width, 200);  // both views side by side
}

TEST(ResolveScene, AppliesAQualityPickAndAnExplicitLayerScaleWins) {
  RuntimeOptions o;
  o.quality = QualitySettings{0.125f, 16, 3};
  const ResolvedScene r = resolve_scene(cloud_scene(), o, 4096);
  EXPECT_EQ(r.substeps, 3);
  EXPECT_EQ(r.scene.footprint.size, 16);
  EXPECT_FLOAT_EQ(r.settings.layer_scale, 0.125f);
  EXPECT_FLOAT_EQ(r.scene.frames_per_second, 72.0f);
  EXPECT_FLOAT_EQ(r.clock.dt, 1.0f / 72.0f);  // three steps per output frame of 1/24 s
  o.layer_scale = 1.0f;
  EXPECT_FLOAT_EQ(resolve_scene(cloud_scene(), o, 4096).settings.layer_scale, 1.0f);
}

TEST(ResolveScene, RefusesAParticleBudgetFromTheDescriptionAlone) {
  // 1500 particles against a budget of 1499: refused before anything exists to allocate.
  const std::string message = refusal_resolve_scene(cloud_scene(R"(, "budget": {"particles": 1499})"), {}, 4096);
  EXPECT_NE(message.find("/budget/particles"), std::string::npos) << message;
  EXPECT_NE(message.find("1500"), std::string::npos) << message;
  EXPECT_EQ(refusal_resolve_scene(cloud_scene(R"(, "budget": {"particles": 1500})"), {}, 4096), "");
}

TEST(ResolveScene, RefusesTargetsWiderThanTheDriverAllows) {
  // 320 pixels wide: fits a 320 limit mono, not side by side (640).
  EXPECT_EQ(refusal_resolve_scene(cloud_scene(), {}, 320), "");
  RuntimeOptions sbs;
  sbs.stereo_mode = StereoMode::side_by_side;
  const std::string message = refusal_resolve_scene(cloud_scene(), sbs, 320);
  EXPECT_NE(message.find("/budget/texture_size"), std::string::npos) << message;
  EXPECT_NE(message.find("640"), std::string::npos) << message;
}

}  // namespace
}  // namespace pyro

namespace pyro {
namespace {

SceneDescription kinds_scene(const std::string& body) { return parse_scene("{" + body + "}", "kinds.json"); }

TEST(ResolveScene, ASetsOwnKindIsKeptBesideOthers) {
  const ResolvedScene r = resolve_scene(
      kinds_scene(R"("clouds": [{"count": 10}, {"count": 10, "particles": "spherical"}])"), RuntimeOptions{}, 4096);
  EXPECT_EQ(r.settings.particles, ParticleShape::gaussian);
  EXPECT_FALSE(r.scene.clouds[0].particles.has_value());
  EXPECT_EQ(r.scene.clouds[1].particles, ParticleShape::spherical);
  RuntimeOptions o;  // --particles draws every set as one kind, to compare kinds
  o.particles = ParticleShape::planar;
  const ResolvedScene forced = resolve_scene(
      kinds_scene(R"("clouds": [{"count": 10, "particles": "spherical"}])"), o, 4096);
  EXPECT_FALSE(forced.scene.clouds[0].particles.has_value());
}

TEST(ResolveScene, ASetsOwnKindIsRefusedWhereItCannotBeHonoured) {
  const std::string explosion = refusal_resolve_scene(
      kinds_scene(R"("render": {"particles": "spherical", "shading": "explosion"},
                     "emitters": [{}, {"particles": "gaussian"}])"),
      RuntimeOptions{}, 4096);
  EXPECT_NE(explosion.find("kinds.json: at /emitters/1/particles:"), std::string::npos) << explosion;
  EXPECT_NE(explosion.find("\"explosion\""), std::string::npos) << explosion;
  const std::string lit = refusal_resolve_scene(
      kinds_scene(R"("shadows": {}, "clouds": [{"count": 10, "particles": "spherical"}])"), RuntimeOptions{}, 4096);
  EXPECT_NE(lit.find("kinds.json: at /clouds/0/particles:"), std::string::npos) << lit;
  // The scene-wide kind written again is no kind of its own: accepted.
  EXPECT_EQ(refusal_resolve_scene(kinds_scene(R"("shadows": {}, "clouds": [{"count": 10, "particles": "gaussian"}])"),
                                  RuntimeOptions{}, 4096),
            "");
}

}  // namespace
}  // namespace pyro
