// The Gaussian splats' vertex shader reads each instance's record through the draw order
// (vertex pulling). In every shipped scene of splats, the particles drawn from the sorting
// system's indexed list and from the gathered copy of it (attributes in draw order, order 0..n-1)
// must give the same bytes; and a list drawn in another order must not, so the order is really
// what the shader follows.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "components/draw_list.h"
#include "components/view.h"
#include "systems/billboard_render/billboard_renderer.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/splat_drawing.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(VertexPulling, IndexedAndGatheredListsDrawTheSameBytesInEveryShippedScene) {
  const std::vector<std::string> scenes = test::gaussian_scenes();
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

    const std::vector<float> indexed =
        test::draw_into_fresh_target(renderer, lists.eyes[0], lists.pools, frame, 96, 72);
    const DrawList gathered = gathered_draw_list(lists, 0);
    ASSERT_FALSE(gathered.indexed());
    ASSERT_EQ(gathered.size(), lists.eyes[0].size()) << name;
    EXPECT_TRUE(indexed == test::draw_into_fresh_target(renderer, gathered, {}, frame, 96, 72)) << name;

    // Front to back instead: "over" blending does not commute, so the bytes change.
    DrawList reversed = lists.eyes[0];
    std::reverse(reversed.order.begin(), reversed.order.end());
    EXPECT_FALSE(indexed == test::draw_into_fresh_target(renderer, reversed, lists.pools, frame, 96, 72)) << name;
    size_t lit = 0;
    for (size_t i = 3; i < indexed.size(); i += 4) lit += indexed[i] > 0.01f;
    EXPECT_GT(lit, indexed.size() / 4 / 20) << name;  // the particles cover part of the view
  }
}

}  // namespace
}  // namespace pyro
