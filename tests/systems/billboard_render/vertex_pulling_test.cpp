// The Gaussian splats' vertex shader reads each instance's record through the draw order
// (vertex pulling). In every shipped scene of splats, the particles drawn from the sorting
// system's indexed list and from the gathered copy of it (attributes in draw order, order 0..n-1)
// must give the same bytes; and a list drawn in another order must not, so the order is really
// what the shader follows.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "components/draw_list.h"
#include "components/view.h"
#include "engine/core/content_path.h"
#include "engine/gpu/render_target.h"
#include "systems/billboard_render/billboard_renderer.h"
#include "systems/scene/scene_loader.h"
#include "systems/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

std::vector<float> draw_into_fresh_target(BillboardRenderer& renderer, const DrawList& list,
                                          const std::vector<const ParticlePool*>& pools,
                                          const CameraFrame& frame) {
  gpu::RenderTarget target(96, 72);
  target.bind();
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  renderer.draw(list, pools, frame, target);
  return target.read_rgba();
}

// The shipped scenes whose particles are Gaussian splats.
std::vector<std::string> gaussian_scenes() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(content_path("scenes"))) {
    if (entry.path().extension() != ".json") continue;
    const SceneDescription scene = load_scene(entry.path().string());
    if (scene.render.particles == ParticleShape::gaussian && (!scene.clouds.empty() || !scene.volumes.empty()))
      names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(VertexPulling, IndexedAndGatheredListsDrawTheSameBytesInEveryShippedScene) {
  const std::vector<std::string> scenes = gaussian_scenes();
  ASSERT_GE(scenes.size(), 4u);  // fog, mist, clouds, cloud_vdb at least
  for (const std::string& name : scenes) {
    RuntimeOptions o;
    o.width_override = 96;
    o.height_override = 72;
    o.readback = false;
    SceneRuntime runtime(load_scene(test::scene_path(name)), o);
    runtime.step();
    runtime.step();
    ecs::World& world = runtime.world();
    const EyeDrawLists& lists = world.resource<EyeDrawLists>();
    ASSERT_TRUE(lists.eyes.at(0).indexed()) << name;
    const CameraFrame frame = world.resource<View>().eyes.at(0);
    BillboardRenderer& renderer = world.resource<BillboardRenderer>();

    const std::vector<float> indexed = draw_into_fresh_target(renderer, lists.eyes[0], lists.pools, frame);
    const DrawList gathered = gathered_draw_list(lists, 0);
    ASSERT_FALSE(gathered.indexed());
    ASSERT_EQ(gathered.size(), lists.eyes[0].size()) << name;
    EXPECT_TRUE(indexed == draw_into_fresh_target(renderer, gathered, {}, frame)) << name;

    // Front to back instead: "over" blending does not commute, so the bytes change.
    DrawList reversed = lists.eyes[0];
    std::reverse(reversed.order.begin(), reversed.order.end());
    EXPECT_FALSE(indexed == draw_into_fresh_target(renderer, reversed, lists.pools, frame)) << name;
    size_t lit = 0;
    for (size_t i = 3; i < indexed.size(); i += 4) lit += indexed[i] > 0.01f;
    EXPECT_GT(lit, indexed.size() / 4 / 20) << name;  // the particles cover part of the view
  }
}

}  // namespace
}  // namespace pyro
