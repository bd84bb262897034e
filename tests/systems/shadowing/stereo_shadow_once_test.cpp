// Shadows and fire lights are light-space work: in stereo the light phase's systems run once a
// frame, not once per eye, while the camera and render phases serve both eyes (the schedule's per-system counts, as
// the profiler reports them), and both eyes see the same particles' light.
#include <gtest/gtest.h>

#include <string>

#include "components/fire_lights.h"
#include "components/particle_light.h"
#include "components/shadow_volume.h"
#include "components/view.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

uint64_t runs_of(const SceneRuntime& runtime, const std::string& system) {
  for (const ecs::SystemStats& s : runtime.schedule().stats())
    if (s.name == system) return s.frames;
  ADD_FAILURE() << "no system named " << system;
  return 0;
}

TEST(StereoShadows, TheLightPhaseRunsOncePerFrameForBothEyes) {
  for (const ShadowMethod method : {ShadowMethod::rays, ShadowMethod::shadow_map}) {
    SceneDescription scene = load_scene(test::scene_path("clouds.json"));
    ShadowSettings s;
    s.method = method;
    scene.shadows = s;
    RuntimeOptions o;
    o.width_override = 64;
    o.height_override = 48;
    o.stereo_mode = StereoMode::left_right;
    SceneRuntime runtime(scene, o);
    for (int f = 0; f < 3; ++f) runtime.draw_frame(f);
    ASSERT_EQ(runtime.world().resource<const View>().eyes.size(), 2u);
    EXPECT_EQ(runs_of(runtime, "shadow_map"), 3u);
    EXPECT_EQ(runs_of(runtime, "shadow_rays"), 3u);
    EXPECT_EQ(runs_of(runtime, "billboard_render"), 3u);  // one run draws both eyes
    // The opaque surfaces' map: built once a frame (each build bumps its version).
    EXPECT_EQ(runtime.world().resource<const ShadowVolume>().version, 3u);
    size_t lit = 0;
    runtime.world().each<const ParticleLight>([&](const ParticleLight& l) { lit += l.others_depth.size(); });
    EXPECT_EQ(lit, 1500u);  // every particle lit, once
  }
}

TEST(StereoShadows, TheExplosionsShadowsAndFireLightsAreWorkedOutOncePerFrame) {
  SceneDescription scene = load_scene(test::scene_path("explosion_dusk.json"));
  ASSERT_TRUE(scene.shadows.has_value());
  RuntimeOptions o;
  o.width_override = 64;
  o.height_override = 64;
  o.stereo_mode = StereoMode::side_by_side;
  SceneRuntime runtime(scene, o);
  for (int f = 0; f < 3; ++f) runtime.draw_frame(f);
  ASSERT_EQ(runtime.world().resource<const View>().eyes.size(), 2u);
  for (const char* system : {"shadow_map", "shadow_rays", "fire_lights", "billboard_render"})
    EXPECT_EQ(runs_of(runtime, system), 3u) << system;
  EXPECT_EQ(runtime.world().resource<const ShadowVolume>().version, 3u);
  EXPECT_EQ(runtime.world().resource<const FireLights>().lights.size(), size_t(scene.shadows->fire_lights));
}

}  // namespace
}  // namespace pyro
