// The Gaussian splats' vertex shader reads each instance's record through the draw order
// (vertex pulling). The same particles drawn from the sorting system's indexed list and from the
// gathered copy of it (records in draw order, order 0..n-1) must give the same bytes; and a
// list drawn in another order must not, so the order is really what the shader follows.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "components/draw_list.h"
#include "components/view.h"
#include "engine/gpu/render_target.h"
#include "systems/billboard_render/billboard_renderer.h"
#include "systems/scene/scene_loader.h"
#include "systems/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

std::vector<float> draw_into_fresh_target(BillboardRenderer& renderer, const DrawList& list,
                                          const std::vector<glm::vec4>& records,
                                          const CameraFrame& frame) {
  gpu::RenderTarget target(96, 72);
  target.bind();
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  renderer.draw(list, records, frame, target);
  return target.read_rgba();
}

TEST(VertexPulling, IndexedAndGatheredListsDrawTheSameBytes) {
  RuntimeOptions o;
  o.width_override = 96;
  o.height_override = 72;
  o.readback = false;
  SceneRuntime runtime(load_scene(test::scene_path("clouds.json")), o);
  runtime.step();
  ecs::World& world = runtime.world();
  const EyeDrawLists& lists = world.resource<EyeDrawLists>();
  ASSERT_TRUE(lists.eyes.at(0).indexed());
  const CameraFrame frame = world.resource<View>().eyes.at(0);
  BillboardRenderer& renderer = world.resource<BillboardRenderer>();

  const std::vector<float> indexed = draw_into_fresh_target(renderer, lists.eyes[0], lists.records, frame);
  const DrawList gathered = gathered_draw_list(lists, 0);
  ASSERT_FALSE(gathered.indexed());
  ASSERT_EQ(gathered.size(), lists.eyes[0].size());
  const std::vector<float> from_gathered = draw_into_fresh_target(renderer, gathered, {}, frame);
  EXPECT_TRUE(indexed == from_gathered);

  // Front to back instead: "over" blending does not commute, so the bytes change.
  DrawList reversed = lists.eyes[0];
  std::reverse(reversed.order.begin(), reversed.order.end());
  const std::vector<float> wrong_order = draw_into_fresh_target(renderer, reversed, lists.records, frame);
  EXPECT_FALSE(indexed == wrong_order);
  size_t lit = 0;
  for (size_t i = 3; i < indexed.size(); i += 4) lit += indexed[i] > 0.01f;
  EXPECT_GT(lit, indexed.size() / 4 / 4);  // the clouds cover a good part of the view
}

}  // namespace
}  // namespace pyro
