// Fire lights the Gaussian splats: a low cloud over campfire.json's fires at night, lit, against
// the CPU reference with the same clustered fire lights (systems/runtime/reference/lit_particle_reference.h,
// point_lights): within the lit clouds' bar, and the frame without fire light is not.
#include <gtest/gtest.h>

#include <cstdio>

#include "components/fire_lights.h"
#include "systems/runtime/quality_picker/quality_measurement.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/rendered_frame.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

constexpr int kWidth = 120, kHeight = 90;

SceneDescription cloud_over_the_campfire(int fire_lights) {
  SceneDescription scene = load_scene(test::scene_path("campfire.json"));
  CloudDescription cloud;
  cloud.name = "smoke";
  cloud.count = 300;
  cloud.radius = 0.12f;
  cloud.density = 0.35f;
  cloud.color = glm::vec3(0.8f);
  cloud.box_min = {-0.9f, 0.75f, -0.4f};
  cloud.box_max = {0.9f, 1.05f, 0.2f};
  scene.clouds = {cloud};
  scene.shadows = ShadowSettings{};
  scene.shadows->fire_lights = fire_lights;
  return scene;
}

RgbImage engine_frame(const SceneDescription& scene) { return test::rendered_frame(scene, kWidth, kHeight, 4); }

TEST(LitCloudsFireLight, SplatsReceiveTheFireAsTheReferenceDoes) {
  const SceneDescription lit = cloud_over_the_campfire(2);
  const RgbImage reference = particle_scene_references(lit, kWidth, kHeight, {4}).at(0);
  const double e = image_rmse(engine_frame(lit), reference);
  const double unlit_by_fire = image_rmse(engine_frame(cloud_over_the_campfire(0)), reference);
  std::printf("fire-lit cloud: rmse %.5f; without the fire light %.5f\n", e, unlit_by_fire);
  EXPECT_LE(e, 0.02);
  EXPECT_GT(unlit_by_fire, 2.0 * e);
}

}  // namespace
}  // namespace pyro
