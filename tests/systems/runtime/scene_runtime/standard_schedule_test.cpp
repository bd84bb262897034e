// The standard schedule SceneRuntime builds: its declarations are true (every frame runs with
// access checking on, so an undeclared access would throw), every conflicting pair of one
// phase is explicitly ordered, phases follow the data (camera before sort), and the eye frames
// are made once per frame, by the stereo_camera system, and read by the sort.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "components/camera.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/small_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

class StandardSchedule : public ::testing::TestWithParam<std::string> {};

TEST_P(StandardSchedule, DeclarationsHoldAndEveryConflictIsOrdered) {
  RuntimeOptions options = test::small_runtime();
  options.readback = true;  // the output phase too
  options.stereo_mode = StereoMode::side_by_side;
  SceneRuntime runtime(load_scene(test::scene_path(GetParam())), options);
  for (int f = 0; f < 3; ++f) ASSERT_NO_THROW(runtime.step()) << "frame " << f;
  ASSERT_NO_THROW(runtime.redraw());

  const ecs::Schedule& schedule = runtime.schedule();
  EXPECT_TRUE(schedule.unordered_conflicts().empty())
      << schedule.unordered_conflicts().front().first << " / "
      << schedule.unordered_conflicts().front().second;
  // There are conflicts (e.g. both emitters write ParticleSet), and they are ordered.
  EXPECT_FALSE(schedule.conflicts().empty());
  for (const auto& [a, b] : schedule.conflicts()) EXPECT_TRUE(schedule.ordered(a, b)) << a << b;

  const auto order = schedule.order();
  const auto at = [&](const char* name) {
    return std::find(order.begin(), order.end(), name) - order.begin();
  };
  for (const char* name : {"cloud_emitter", "emitter", "cloud_drift", "animation", "lighting", "camera_orbit",
                           "stereo_camera", "sorting", "flipbook_orient", "mesh_render",
                           "flipbook_render", "billboard_render", "composite", "frame_readback"})
    EXPECT_LT(at(name), std::ssize(order)) << name;
  EXPECT_LT(at("animation"), at("lighting"));
  EXPECT_LT(at("lighting"), at("stereo_camera"));
  EXPECT_LT(at("stereo_camera"), at("sorting"));
  EXPECT_LT(at("stereo_camera"), at("flipbook_orient"));
  // One light block a frame, packed after every light is known and on the GPU before any draw.
  EXPECT_LT(at("fire_lights"), at("light_block"));
  EXPECT_LT(at("lighting"), at("light_block"));
  EXPECT_LT(at("light_upload"), at("mesh_render"));
  EXPECT_LT(at("light_upload"), at("billboard_render"));
  for (const ecs::SystemDesc& s : schedule.systems()) {
    // GL work only in the render, composite and output phases, all of it on the GL thread.
    EXPECT_EQ(s.main_thread, s.phase >= ecs::Phase::render) << s.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, StandardSchedule,
                         ::testing::Values("fog.json", "clouds.json", "explosion.json",
                                           "campfire.json", "cloud_vdb.json"),
                         [](const auto& info) {
                           std::string name = info.param.substr(0, info.param.find('.'));
                           return name;
                         });

TEST(StandardSchedule, EyeFramesComeFromTheCameraSystemOnly) {
  // The sort declares no access to the camera: under the schedule it could not read one.
  SceneRuntime runtime(load_scene(test::scene_path("fog.json")), test::small_runtime());
  for (const ecs::SystemDesc& s : runtime.schedule().systems()) {
    if (s.name == "stereo_camera") continue;
    EXPECT_EQ(s.access.mode(ecs::type_id<Camera>()) == ecs::AccessMode::write,
              s.name == "camera_orbit")
        << s.name;
    if (s.phase >= ecs::Phase::sort) {
      EXPECT_EQ(s.access.mode(ecs::type_id<Camera>()), ecs::AccessMode::none) << s.name;
    }
  }
}

}  // namespace
}  // namespace pyro
