#include "systems/runtime/scene_runtime/build_world.h"

#include <cmath>

#include "components/ambient_light.h"
#include "components/anisotropic_cloud.h"
#include "components/camera.h"
#include "components/camera_orbit.h"
#include "components/cloud_volume.h"
#include "components/directional_light.h"
#include "components/emitter.h"
#include "components/light_keyframes.h"
#include "components/gpu_frame.h"
#include "components/mesh_instance.h"
#include "components/particle_dynamics.h"
#include "components/particle_light.h"
#include "components/particle_kind.h"
#include "components/particle_set.h"
#include "components/shadow_settings.h"
#include "components/simulation_environment.h"
#include "components/volume_sequence.h"
#include "engine/core/rng.h"
#include "systems/animation/particle_prewarm.h"
#include "systems/billboard_render/billboard_renderer.h"
#include "systems/composite/frame_targets.h"
#include "systems/runtime/scene_runtime/mesh_geometry.h"

namespace pyro {

namespace {

void add_camera(ecs::World& world, const CameraDescription& d, const StereoCamera& stereo) {
  const ecs::Entity camera = world.create();
  Camera& cam = world.emplace<Camera>(camera);
  cam.position = d.position;
  cam.target = d.target;
  cam.up = d.up;
  cam.fov_y_deg = d.fov_y_deg;
  cam.near = d.near;
  cam.far = d.far;
  world.emplace<StereoCamera>(camera, stereo);
  if (d.orbit_deg_per_second != 0.0f)
    world.emplace<CameraOrbit>(camera, CameraOrbit{d.position, d.orbit_deg_per_second});
}

void add_clouds(ecs::World& world, const SceneDescription& scene) {
  for (size_t k = 0; k < scene.clouds.size(); ++k) {
    const CloudDescription& d = scene.clouds[k];
    const ecs::Entity e = world.create();
    CloudVolume c;
    c.box_min = d.box_min;
    c.box_max = d.box_max;
    c.count = d.count;
    c.radius = d.radius;
    c.density = d.density;
    c.color = d.color;
    c.seed = mix_seeds(scene.seed, d.seed * 1000003ull + k);
    c.drift = d.drift;
    c.jitter = d.jitter;
    world.emplace<CloudVolume>(e, c);
    world.emplace<ParticleSet>(e, ParticleSet{ParticlePool(d.count)});
    if (d.particles) world.emplace<ParticleKind>(e, ParticleKind{*d.particles});
  }
}

// Volumes: particles fixed since loading; the sorting and billboard systems draw them like any
// other ParticleSet. Anisotropic particles (a version 2 particle file) are an AnisotropicCloud,
// drawn by the billboard system's anisotropic pass.
void add_volumes(ecs::World& world, std::vector<VolumeAsset>& volumes) {
  for (VolumeAsset& v : volumes) {
    const ecs::Entity e = world.create();
    if (!v.anisotropic.empty())
      world.emplace<AnisotropicCloud>(e, AnisotropicCloud{std::move(v.anisotropic)});
    else
      world.emplace<ParticleSet>(e, ParticleSet{std::move(v.particles)});
    world.emplace<VolumeSource>(e, std::move(v.source));
    if (v.sequence) world.emplace<VolumeSequence>(e, std::move(*v.sequence));
  }
}

void add_emitters(ecs::World& world, const SceneDescription& scene) {
  for (size_t k = 0; k < scene.emitters.size(); ++k) {
    const EmitterDescription& d = scene.emitters[k];
    const ecs::Entity e = world.create();
    Emitter em = d.emitter;
    // Its own stream: the scene seed mixed with the emitter's seed and its place in the file
    // (a different odd constant from the clouds', so an emitter and a cloud never share one).
    em.seed = mix_seeds(scene.seed, d.emitter.seed * 2654435761ull + k + 0x5EEDull);
    em.rng = Rng(em.seed);
    world.emplace<Emitter>(e, std::move(em));
    world.emplace<ParticleDynamics>(e, d.dynamics);
    world.emplace<ParticleSet>(e, ParticleSet{ParticlePool(d.emitter.budget)});
    if (d.particles) world.emplace<ParticleKind>(e, ParticleKind{*d.particles});
  }
}

// Each mesh with its geometry: a file's from the assets, a primitive's built here.
void add_meshes(ecs::World& world, const std::vector<MeshDescription>& meshes,
                const std::vector<std::shared_ptr<const SharedMesh>>& files) {
  for (size_t i = 0; i < meshes.size(); ++i) {
    const MeshDescription& m = meshes[i];
    std::shared_ptr<const SharedMesh> geometry =
        m.kind == MeshKind::file ? (i < files.size() ? files[i] : nullptr) : primitive_geometry(m);
    world.emplace<MeshInstance>(world.create(), MeshInstance{m.kind, std::move(geometry),
                                                             MeshPlacement{m.position, m.rotation_deg, m.scale}, m.color});
  }
}

// The scene's lights as entities, created after every other entity: entity indices order the
// particles' draw and seed the explosion's detail noise, so they must not move.
void add_lights(ecs::World& world, const SceneDescription& scene) {
  for (size_t i = 0; i < scene.directional_lights.size(); ++i) {
    const ecs::Entity e = world.create();
    world.emplace<DirectionalLight>(e, scene.directional_lights[i]);
    if (i < scene.light_keyframes.size() && !scene.light_keyframes[i].keys.empty())
      world.emplace<LightKeyframes>(e, scene.light_keyframes[i]);
  }
  for (const AmbientLight& light : scene.ambient_lights) world.emplace<AmbientLight>(world.create(), light);
}

// Lit media (a "shadows" block): the light phase's settings, and a ParticleLight beside every
// particle set and anisotropic cloud for it to write.
void add_shadowing(ecs::World& world, const SceneDescription& scene) {
  if (!scene.shadows) return;
  world.set_resource<ShadowSettings>(*scene.shadows);
  std::vector<ecs::Entity> sets;
  world.each<const ParticleSet>([&](ecs::Entity e, const ParticleSet&) { sets.push_back(e); });
  world.each<const AnisotropicCloud>([&](ecs::Entity e, const AnisotropicCloud&) { sets.push_back(e); });
  for (const ecs::Entity e : sets) world.emplace<ParticleLight>(e);
}

}  // namespace

ecs::World build_world(const ResolvedScene& resolved, SceneAssets assets) {
  const SceneDescription& scene = resolved.scene;
  ecs::World world;
  world.set_resource<RenderSettings>(resolved.settings);
  world.set_resource<ExplosionShading>(resolved.shading);
  world.set_resource<FrameClock>(resolved.clock);
  add_camera(world, scene.camera, resolved.stereo);
  add_clouds(world, scene);
  add_volumes(world, assets.volumes);
  world.set_resource<SimulationEnvironment>(scene.environment);
  add_emitters(world, scene);
  add_meshes(world, scene.meshes, assets.meshes);
  add_flipbook_fires(world, assets.fires, assets.flipbooks);
  add_lights(world, scene);
  add_shadowing(world, scene);
  world.set_resource<GpuFrame>(make_gpu_frame(resolved.settings));
  world.set_resource<BillboardRenderer>(
      make_footprint_table(scene.footprint.size, scene.footprint.intervals));
  if (scene.prewarm > 0.0f)
    prewarm_particles(world, static_cast<uint64_t>(std::llround(scene.prewarm / resolved.clock.dt)));
  return world;
}

}  // namespace pyro
