// clouds.json lit by its sun, against the CPU reference with exact shadows
// (systems/runtime/reference/lit_particle_reference.h): single scattering with the sun's transmittance
// exact at every point of every ray, over the opaque scene whose ground keeps exp(-tau) of its
// sunlight. Both shadow methods must come within the bar (whole-frame RMSE 0.02); lit without
// shadows, the same frame must not. The splats' sunlight evaluated at the billboards' vertices
// (a plane across each) comes within the looser bar of 0.025 (0.019 with the lobe and octaves).
#include <gtest/gtest.h>

#include <cstdio>

#include "components/frame_image.h"
#include "systems/runtime/quality_picker/quality_measurement.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/rendered_frame.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

constexpr int kLitCloudsVsReferenceWidth = 160, kLitCloudsVsReferenceHeight = 120;

SceneDescription lit_clouds(ShadowMethod method, SplatSunlight sunlight = SplatSunlight::fragments) {
  SceneDescription scene = load_scene(test::scene_path("clouds.json"));
  ShadowSettings s;
  s.method = method;
  s.splat_sunlight = sunlight;
  scene.shadows = s;
  return scene;
}

RgbImage engine_frame_lit_clouds_vs_reference(const SceneDescription& scene) { return test::rendered_frame(scene, kLitCloudsVsReferenceWidth, kLitCloudsVsReferenceHeight); }

class LitClouds : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    reference_ = new RgbImage(particle_scene_references(lit_clouds(ShadowMethod::rays), kLitCloudsVsReferenceWidth, kLitCloudsVsReferenceHeight, {0}).at(0));
  }
  static void TearDownTestSuite() { delete reference_; }
  static double rmse(ShadowMethod method, SplatSunlight sunlight = SplatSunlight::fragments) {
    const RgbImage img = engine_frame_lit_clouds_vs_reference(lit_clouds(method, sunlight));
    const double e = image_rmse(img, *reference_);
    std::printf("%s, sunlight at the %s: rmse %.5f\n", name_of(method).data(), name_of(sunlight).data(), e);
    return e;
  }
  static RgbImage* reference_;
};
RgbImage* LitClouds::reference_ = nullptr;

TEST_F(LitClouds, ExactShadowRaysAreWithinTheBar) { EXPECT_LE(rmse(ShadowMethod::rays), 0.02); }

TEST_F(LitClouds, TheOpacityShadowMapIsWithinTheBar) { EXPECT_LE(rmse(ShadowMethod::shadow_map), 0.02); }

TEST_F(LitClouds, WithoutShadowsTheFrameIsNot) { EXPECT_GT(rmse(ShadowMethod::none), 0.02); }

TEST_F(LitClouds, TheSunlightAtTheVerticesIsWithinTheLooserBar) {
  EXPECT_LE(rmse(ShadowMethod::shadow_map, SplatSunlight::vertices), 0.025);
}

// A forward lobe and four octaves (engine/math/scattering_octaves.h): the splats and the
// reference light the clouds alike, and differently from single scattering.
TEST(LitCloudsScattering, ForwardLobeAndOctavesMatchTheReference) {
  SceneDescription scene = lit_clouds(ShadowMethod::shadow_map);
  scene.shadows->scattering = {0.6, {4, 0.25, 0.5, 0.5}};
  const RgbImage engine = engine_frame_lit_clouds_vs_reference(scene);
  scene.shadows->method = ShadowMethod::rays;
  const RgbImage reference = particle_scene_references(scene, kLitCloudsVsReferenceWidth, kLitCloudsVsReferenceHeight, {0}).at(0);
  const double e = image_rmse(engine, reference);
  const double single = image_rmse(engine_frame_lit_clouds_vs_reference(lit_clouds(ShadowMethod::shadow_map)), reference);
  std::printf("octaves: rmse %.5f; single scattering against them %.5f\n", e, single);
  EXPECT_LE(e, 0.02);
  EXPECT_GT(single, 2.0 * e);
  // The lobe and octaves at the vertices (LIT 2's plane).
  scene.shadows->method = ShadowMethod::shadow_map;
  scene.shadows->splat_sunlight = SplatSunlight::vertices;
  const double at_vertices = image_rmse(engine_frame_lit_clouds_vs_reference(scene), reference);
  std::printf("octaves, sunlight at the vertices: rmse %.5f\n", at_vertices);
  EXPECT_LE(at_vertices, 0.019);
}

}  // namespace
}  // namespace pyro
