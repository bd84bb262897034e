// The runtime's third layer alone: a hand-made ResolvedScene and SceneAssets (no scene file, no
// asset file) become the expected entities and resources.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

#include "components/ambient_light.h"
#include "components/camera.h"
#include "components/cloud_volume.h"
#include "components/directional_light.h"
#include "components/emitter.h"
#include "components/frame_clock.h"
#include "components/gpu_frame.h"
#include "components/mesh_instance.h"
#include "components/particle_set.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "components/volume_source.h"
#include "systems/runtime/scene_runtime/build_world.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

ResolvedScene hand_made_scene() {
  ResolvedScene r;
  r.scene.clouds.resize(2);
  r.scene.clouds[0].count = 10;
  r.scene.clouds[1].count = 20;
  r.scene.emitters.resize(1);
  r.scene.emitters[0].emitter.budget = 30;
  r.scene.meshes.resize(1);
  r.scene.meshes[0].scale = 4.0f;
  r.scene.camera.orbit_deg_per_second = 0.0f;
  r.settings.width = 32;
  r.settings.height = 24;
  r.stereo.eye_order = EyeOrder::right_left;
  r.clock.dt = 0.125f;
  return r;
}

SceneAssets three_particle_volume() {
  SceneAssets assets;
  VolumeAsset v;
  v.particles = ParticlePool(3);
  for (int i = 0; i < 3; ++i) v.particles.spawn(ParticleInit{});
  v.source.path = "hand-made";
  v.source.particles = 3;
  assets.volumes.push_back(std::move(v));
  return assets;
}

template <class C>
size_t count(ecs::World& w) {
  size_t n = 0;
  w.each<C>([&](C&) { ++n; });
  return n;
}

TEST(BuildWorld, MakesOneEntityPerDescribedThing) {
  shared_headless_context().make_current();
  ecs::World w = build_world(hand_made_scene(), three_particle_volume());
  EXPECT_EQ(count<Camera>(w), 1u);
  EXPECT_EQ(count<StereoCamera>(w), 1u);
  EXPECT_EQ(count<CloudVolume>(w), 2u);
  EXPECT_EQ(count<VolumeSource>(w), 1u);
  EXPECT_EQ(count<Emitter>(w), 1u);
  EXPECT_EQ(count<MeshInstance>(w), 1u);
  EXPECT_EQ(count<ParticleSet>(w), 4u);  // two clouds, the volume, the emitter
  EXPECT_EQ(count<DirectionalLight>(w), 1u);
  EXPECT_EQ(count<AmbientLight>(w), 1u);
  // The lights come last: the other entities keep the indices they had before lights were
  // entities (indices order the draw and seed the explosion's noise).
  uint32_t last_other = 0, first_light = UINT32_MAX;
  w.each<ParticleSet>([&](ecs::Entity e, ParticleSet&) { last_other = std::max(last_other, e.index); });
  w.each<MeshInstance>([&](ecs::Entity e, MeshInstance&) { last_other = std::max(last_other, e.index); });
  w.each<DirectionalLight>([&](ecs::Entity e, DirectionalLight&) { first_light = std::min(first_light, e.index); });
  w.each<AmbientLight>([&](ecs::Entity e, AmbientLight&) { first_light = std::min(first_light, e.index); });
  EXPECT_GT(first_light, last_other);
  std::vector<size_t> capacities, sizes;
  w.each<ParticleSet>([&](ParticleSet& s) {
    capacities.push_back(s.pool.capacity());
    sizes.push_back(s.pool.size());
  });
  EXPECT_EQ(capacities, (std::vector<size_t>{10, 20, 3, 30}));  // in entity order
  EXPECT_EQ(sizes, (std::vector<size_t>{0, 0, 3, 0}));            // only the volume is loaded
  w.each<StereoCamera>([](StereoCamera& s) { EXPECT_EQ(s.eye_order, EyeOrder::right_left); });
  w.each<MeshInstance>([](MeshInstance& m) { EXPECT_FLOAT_EQ(m.placement.scale, 4.0f); });
  EXPECT_EQ(w.resource<RenderSettings>().width, 32);
  EXPECT_FLOAT_EQ(w.resource<FrameClock>().dt, 0.125f);
  EXPECT_EQ(w.resource<FrameClock>().frame, 0u);
  EXPECT_EQ(w.resource<GpuFrame>().output->width(), 32);
}

}  // namespace
}  // namespace pyro
