// The Gaussian splats' draw order made on the GPU (systems/gpu_sorting) changes no image: every
// shipped scene of Gaussian particles (those without a particle set too), mono and side by side, with billboards facing the viewplane (one
// order by view depth, culled by both eyes) and the viewpoint (an order by distance per eye),
// renders the same bytes with the order made on the CPU and on the GPU. And under "auto" the
// runtime measures both and follows its measurement.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "components/draw_list.h"
#include "components/frame_image.h"
#include "components/render_settings.h"
#include "components/sort_device_choice.h"
#include "engine/core/content_path.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/splat_drawing.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

std::vector<std::vector<float>> frames(const SceneDescription& scene, StereoMode mode,
                                       BillboardAlignment alignment, SortDevice device) {
  RuntimeOptions o;
  o.width_override = 80;
  o.height_override = 60;
  o.stereo_mode = mode;
  o.alignment = alignment;
  o.sort_device = device;
  SceneRuntime run(scene, o);
  std::vector<std::vector<float>> images;
  for (int frame = 0; frame < 3; ++frame) {
    run.step();
    EXPECT_EQ(run.world().resource<EyeDrawLists>().eyes.at(0).on_gpu, device == SortDevice::gpu);
    images.push_back(run.image().rgba);
  }
  return images;
}

// The shipped scenes whose particles are Gaussian: splats from clouds and volumes, or a volume of
// anisotropic particles alone (no particle set to order).
std::vector<std::string> gaussian_particle_scenes() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(content_path("scenes")))
    if (entry.path().extension() == ".json" &&
        load_scene(entry.path().string()).render.particles == ParticleShape::gaussian)
      names.push_back(entry.path().filename().string());
  return names;
}

TEST(GpuSortFrames, EveryShippedSceneOfGaussiansRendersTheSameBytesWithTheGpuOrder) {
  const std::vector<std::string> scenes = gaussian_particle_scenes();
  ASSERT_GE(scenes.size(), 5u);  // fog, mist, clouds, cloud_vdb, cloud_fitted at least
  for (const std::string& name : scenes) {
    SceneDescription scene = load_scene(test::scene_path(name));
    scene.quality = {};
    for (const StereoMode mode : {StereoMode::mono, StereoMode::side_by_side})
      for (const BillboardAlignment a : {BillboardAlignment::viewplane, BillboardAlignment::viewpoint}) {
        const auto cpu = frames(scene, mode, a, SortDevice::cpu), gpu = frames(scene, mode, a, SortDevice::gpu);
        for (size_t f = 0; f < cpu.size(); ++f)
          EXPECT_TRUE(cpu[f] == gpu[f]) << name << ", stereo " << int(mode) << ", alignment "
                                         << int(a) << ", frame " << f;
      }
  }
}

TEST(GpuSortFrames, AutoMeasuresBothDevicesAndFollowsTheFaster) {
  RuntimeOptions o;
  o.width_override = 64;
  o.height_override = 48;
  o.readback = false;
  o.sort_device = SortDevice::automatic;
  SceneRuntime run(load_scene(test::scene_path("clouds.json")), o);
  run.step();
  ecs::World& world = run.world();
  EXPECT_FALSE(world.resource<SortDeviceChoice>().measured);  // the first frame grows the CPU's space
  run.step();
  const SortDeviceChoice choice = world.resource<SortDeviceChoice>();
  ASSERT_TRUE(choice.measured);
  EXPECT_GT(choice.cpu_ms, 0.0);
  EXPECT_GT(choice.gpu_ms, 0.0);
  EXPECT_GT(choice.particles, 0u);
  EXPECT_EQ(choice.gpu, choice.gpu_ms < choice.cpu_ms);
  run.step();
  EXPECT_EQ(world.resource<EyeDrawLists>().eyes.at(0).on_gpu, choice.gpu);
  // The other measurement followed too: the next frame orders where the choice says.
  world.resource<SortDeviceChoice>().gpu = !choice.gpu;
  run.step();
  EXPECT_EQ(world.resource<EyeDrawLists>().eyes.at(0).on_gpu, !choice.gpu);
}

}  // namespace
}  // namespace pyro
