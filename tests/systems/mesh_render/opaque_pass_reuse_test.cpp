// The opaque pass draws a still scene once (systems/mesh_render/mesh_renderer.h): later frames
// copy its image back when particles were blended into the scene target on top of it, or find it
// in place when the particles went into layers, the same bytes a draw gives either way; anything
// the image depends on changing draws it again.
#include <gtest/gtest.h>

#include <vector>

#include "components/frame_image.h"
#include "components/mesh_instance.h"
#include "systems/mesh_render/mesh_renderer.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

// Gaussian particles at full resolution blend into the scene target over a ground and a tower.
SceneDescription meshes_under_fog() {
  SceneDescription s;
  s.width = 96;
  s.height = 64;
  s.camera.position = {0.0f, 3.0f, 12.0f};
  s.camera.target = {0.0f, 2.0f, 0.0f};
  MeshDescription ground;
  ground.kind = MeshKind::ground_plane;
  ground.scale = 20.0f;
  MeshDescription tower;
  tower.kind = MeshKind::water_tower;
  tower.position = {2.0f, 0.0f, -1.0f};
  s.meshes = {ground, tower};
  CloudDescription c;
  c.count = 40;
  c.radius = 0.8f;
  c.box_min = {-3.0f, 0.5f, -2.0f};
  c.box_max = {3.0f, 3.0f, 2.0f};
  c.drift = {0.4f, 0.0f, 0.0f};
  s.clouds.push_back(c);
  return s;
}

// `frames` images of `run`; with `fresh`, a new renderer (nothing to reuse) before each frame.
std::vector<std::vector<float>> images(SceneRuntime& run, int frames, bool fresh,
                                       bool move_tower_at_2 = false) {
  std::vector<std::vector<float>> out;
  for (int f = 0; f < frames; ++f) {
    if (fresh) run.world().set_resource<MeshRenderer>();
    if (move_tower_at_2 && f == 2)
      run.world().each<MeshInstance>([](MeshInstance& m) {
        if (m.kind == MeshKind::water_tower) m.placement.position.x += 0.5f;
      });
    run.step();
    out.push_back(run.image().rgba);
  }
  return out;
}

TEST(OpaquePassReuse, AStillSceneIsDrawnOnceAndGivesTheSameImages) {
  const SceneDescription scene = meshes_under_fog();
  SceneRuntime reused(scene), drawn(scene);
  const auto a = images(reused, 4, false), b = images(drawn, 4, true);
  for (size_t f = 0; f < a.size(); ++f) EXPECT_EQ(a[f], b[f]) << f;
  EXPECT_NE(a[0], a[3]);  // the fog drifted: the particles were drawn every frame
  const MeshRenderer& r = reused.world().resource<MeshRenderer>();
  EXPECT_EQ(r.meshes_drawn(), 1);
  EXPECT_EQ(r.images_restored(), 3);  // the fog was blended into the scene target each frame
}

TEST(OpaquePassReuse, WithParticlesInLayersTheImageStaysInPlace) {
  SceneDescription scene = meshes_under_fog();
  scene.render.particles = ParticleShape::spherical;
  scene.render.shading = ParticleShading::explosion;
  scene.render.layer_scale = 0.5f;
  SceneRuntime reused(scene), drawn(scene);
  const auto a = images(reused, 4, false), b = images(drawn, 4, true);
  for (size_t f = 0; f < a.size(); ++f) EXPECT_EQ(a[f], b[f]) << f;
  EXPECT_NE(a[0], a[3]);
  const MeshRenderer& r = reused.world().resource<MeshRenderer>();
  EXPECT_EQ(r.meshes_drawn(), 1);
  EXPECT_EQ(r.images_restored(), 0);
}

TEST(OpaquePassReuse, AMovedMeshIsDrawnAgain) {
  const SceneDescription scene = meshes_under_fog();
  SceneRuntime reused(scene), drawn(scene);
  const auto a = images(reused, 4, false, true), b = images(drawn, 4, true, true);
  for (size_t f = 0; f < a.size(); ++f) EXPECT_EQ(a[f], b[f]) << f;
  EXPECT_EQ(reused.world().resource<MeshRenderer>().meshes_drawn(), 2);
}

TEST(OpaquePassReuse, AMovingCameraIsDrawnEveryFrame) {
  SceneDescription scene = meshes_under_fog();
  scene.camera.orbit_deg_per_second = 20.0f;
  SceneRuntime reused(scene), drawn(scene);
  const auto a = images(reused, 3, false), b = images(drawn, 3, true);
  for (size_t f = 0; f < a.size(); ++f) EXPECT_EQ(a[f], b[f]) << f;
  EXPECT_EQ(reused.world().resource<MeshRenderer>().meshes_drawn(), 3);
}

}  // namespace
}  // namespace pyro
