// SceneRuntime::redraw (the viewer paused): the last frame drawn again, at its own time, without
// touching the simulation — the same image as the step that drew it, the same particles after,
// and the clock where it was.
#include <gtest/gtest.h>

#include "components/frame_clock.h"
#include "components/particle_set.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(SceneRuntimeRedraw, GivesTheImageOfTheLastStepAndLeavesTheSimulationAlone) {
  // The explosion's heat shimmer moves with time: an image drawn at another frame's time differs.
  const SceneDescription scene = load_scene(test::scene_path("explosion.json"));
  RuntimeOptions o;
  o.readback = false;
  o.width_override = 64;
  o.height_override = 48;
  SceneRuntime runtime(scene, o);
  for (int f = 0; f < 6; ++f) runtime.step();
  const auto stepped = runtime.read_output();
  const uint64_t frame = runtime.frame();
  float x0 = 0;
  runtime.world().each<ParticleSet>([&](ParticleSet& s) {
    if (s.pool.size() && x0 == 0) x0 = s.pool.px[0];
  });
  runtime.redraw();
  runtime.redraw();
  EXPECT_EQ(runtime.frame(), frame);
  float x1 = 0;
  runtime.world().each<ParticleSet>([&](ParticleSet& s) {
    if (s.pool.size() && x1 == 0) x1 = s.pool.px[0];
  });
  EXPECT_EQ(x1, x0);
  const auto redrawn = runtime.read_output();
  ASSERT_EQ(redrawn.rgba.size(), stepped.rgba.size());
  EXPECT_TRUE(redrawn.rgba == stepped.rgba) << "redraw changed the image";
  // One more step moves on: the image changes (the scene is not static).
  runtime.step();
  EXPECT_FALSE(runtime.read_output().rgba == stepped.rgba);
}

}  // namespace
}  // namespace pyro
