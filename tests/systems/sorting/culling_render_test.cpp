// Culling before the sort leaves out only particles that draw nothing: in every shipped scene of
// Gaussian splats, from the scene's camera and from a camera inside the particles looking along
// each axis, the culled draw list gives the same bytes as the whole one, and leaves particles out.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "components/draw_list.h"
#include "components/view.h"
#include "engine/math/view_frustum.h"
#include "systems/billboard_render/billboard_renderer.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "systems/sorting/depth_sort.h"
#include "tests/support/splat_drawing.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

constexpr int kCullingRenderWidth = 96, kCullingRenderHeight = 72;

// The particles' mean position: a camera there stands among them.
glm::vec3 centre_of(const std::vector<const ParticlePool*>& pools) {
  glm::dvec3 sum(0.0);
  size_t n = 0;
  for (const ParticlePool* p : pools)
    for (size_t i = 0; i < p->size(); ++i, ++n) sum += glm::dvec3(p->px[i], p->py[i], p->pz[i]);
  return glm::vec3(sum / double(std::max<size_t>(n, 1)));
}

TEST(CullingRender, TheCulledListDrawsTheSameBytesAsTheWholeOne) {
  const std::vector<std::string> scenes = test::gaussian_scenes();
  ASSERT_GE(scenes.size(), 4u);
  size_t views = 0, views_that_cull = 0;
  for (const std::string& name : scenes) {
    RuntimeOptions o;
    o.width_override = kCullingRenderWidth;
    o.height_override = kCullingRenderHeight;
    o.readback = false;
    SceneRuntime runtime(load_scene(test::scene_path(name)), o);
    runtime.step();
    ecs::World& world = runtime.world();
    BillboardRenderer& renderer = world.resource<BillboardRenderer>();
    SortScratch scratch;
    collect_particle_sets(world, scratch);
    std::vector<const ParticlePool*> pools;
    for (const auto& set : scratch.sets) pools.push_back(set.second);
    const CameraFrame scene_camera = world.resource<View>().eyes.at(0);
    std::vector<CameraFrame> cameras = {scene_camera};
    const glm::vec3 inside = centre_of(pools);
    for (const glm::vec3 look : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 0, 1),
                                 glm::vec3(0, 0, -1), glm::vec3(0.3f, -1, 0.2f)})
      cameras.push_back(make_camera_frame(inside, inside + look, {0, 1, 0}, 50.0f, 0.05f,
                                          scene_camera.far, kCullingRenderWidth, kCullingRenderHeight));
    for (const CameraFrame& camera : cameras) {
      DrawList whole, culled;
      const ViewFrustum frustum = view_frustum(camera);
      order_draw_list(camera.eye, camera.forward, SortKeyKind::view_depth, scratch, whole);
      order_draw_list(camera.eye, camera.forward, SortKeyKind::view_depth, scratch, culled,
                      std::span<const ViewFrustum>(&frustum, 1));
      ASSERT_LE(culled.size(), whole.size()) << name;
      ++views;
      views_that_cull += culled.size() < whole.size();
      const std::vector<float> expected =
          test::draw_into_fresh_target(renderer, whole, pools, camera, kCullingRenderWidth, kCullingRenderHeight);
      EXPECT_TRUE(expected == test::draw_into_fresh_target(renderer, culled, pools, camera, kCullingRenderWidth, kCullingRenderHeight)) << name << ", camera at "
          << camera.eye.x << " " << camera.eye.y << " " << camera.eye.z;
    }
  }
  // From inside the particles most views leave some out: the comparison is not vacuous.
  EXPECT_GE(views_that_cull, views / 2);
}

}  // namespace
}  // namespace pyro
