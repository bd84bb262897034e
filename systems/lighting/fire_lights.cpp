#include "systems/lighting/fire_lights.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <tbb/parallel_for.h>

#include "components/anisotropic_cloud.h"
#include "components/fire_lights.h"
#include "components/flipbook_emission.h"
#include "components/flipbook_fire.h"
#include "components/frame_clock.h"
#include "components/particle_light.h"
#include "components/particle_medium.h"
#include "components/particle_set.h"
#include "components/render_settings.h"
#include "components/shadow_settings.h"
#include "engine/math/shadow_ray_index.h"
#include "engine/math/sphere_line_integral.h"
#include "systems/lighting/flipbook_fire_lights.h"
#include "systems/shadowing/shadowing_systems.h"

namespace pyro {

namespace {

// The fire shader's emission table (systems/billboard_render/explosion_renderer.cpp), made again
// only when the shading changes.
struct FireEmissionCache {
  ExplosionShading shading;
  BlackbodyTable table;
  bool made = false;
};

const BlackbodyTable& emission_table(ecs::World& world, const ExplosionShading& shading) {
  FireEmissionCache& cache = world.resource<FireEmissionCache>();
  if (!cache.made || !(cache.shading == shading)) {
    cache.table = blackbody_emission_table(shading.fire_t_min, shading.fire_t_max, shading.fire_emission, 128);
    cache.shading = shading;
    cache.made = true;
  }
  return cache.table;
}

// The flipbook fires' billboards as emitters, in entity order.
void add_flipbook_emitters(ecs::World& world, std::vector<PointEmitter>& emitters) {
  const FrameClock* clock = world.try_resource<const FrameClock>();
  const double seconds = clock ? clock->time() : 0.0;
  std::vector<std::pair<uint32_t, std::vector<PointEmitter>>> fires;
  world.each<const FlipbookFire, const FlipbookEmission>(
      [&](ecs::Entity e, const FlipbookFire& fire, const FlipbookEmission& emission) {
        fires.push_back({e.index, flipbook_fire_emitters(fire, emission, seconds)});
      });
  std::sort(fires.begin(), fires.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& fire : fires) emitters.insert(emitters.end(), fire.second.begin(), fire.second.end());
}

// The explosion's fire particles as emitters.
void add_explosion_emitters(ecs::World& world, std::vector<PointEmitter>& emitters) {
  const ExplosionShading* current = world.try_resource<const ExplosionShading>();
  const ExplosionShading shading = current ? *current : ExplosionShading{};
  const BlackbodyTable& table = emission_table(world, shading);
  std::vector<std::pair<uint32_t, const ParticlePool*>> sets;
  world.each<const ParticleSet>([&](ecs::Entity e, const ParticleSet& s) { sets.push_back({e.index, &s.pool}); });
  std::sort(sets.begin(), sets.end());  // entity-index order: the same lights whatever the storage
  std::vector<const ParticlePool*> pools;
  for (const auto& set : sets) pools.push_back(set.second);
  const std::vector<PointEmitter> fire = fire_emitters(pools, shading, table, shadow_casters(world));
  emitters.insert(emitters.end(), fire.begin(), fire.end());
}

void run_fire_lights(ecs::World& world) {
  FireLights& out = world.resource<FireLights>();
  out.lights.clear();
  out.emitters.clear();
  const ShadowSettings* settings = world.try_resource<const ShadowSettings>();
  const RenderSettings* render = world.try_resource<const RenderSettings>();
  if (!settings || settings->fire_lights <= 0 || !render) return;
  if (render->media_layers()) add_explosion_emitters(world, out.emitters);
  add_flipbook_emitters(world, out.emitters);
  out.lights = cluster_point_lights(out.emitters, std::min(settings->fire_lights, kMaxFireLights));
}

}  // namespace

std::vector<PointEmitter> fire_emitters(const std::vector<const ParticlePool*>& pools,
                                        const ExplosionShading& shading, const BlackbodyTable& emission,
                                        const std::vector<ShadowCaster>& casters) {
  std::vector<ShadowRayIndex> outward;  // toward +x, -x, +y, -y, +z, -z
  for (int a = 0; a < 6; ++a) {
    glm::dvec3 toward(0.0);
    toward[a / 2] = a % 2 ? -1.0 : 1.0;
    outward.emplace_back(casters, -toward);
  }
  // The fire particles, then each one's emitter in parallel (the escape is most of the work).
  std::vector<std::pair<const ParticlePool*, std::size_t>> fire;
  for (const ParticlePool* pool : pools)
    for (std::size_t i = 0; i < pool->size(); ++i)
      if (pool->medium[i] == static_cast<uint8_t>(ParticleMedium::fire) && pool->density[i] > 0.0f)
        fire.push_back({pool, i});
  std::vector<PointEmitter> out(fire.size());
  tbb::parallel_for(std::size_t(0), fire.size(), [&](std::size_t f) {
    const ParticlePool& p = *fire[f].first;
    const std::size_t i = fire[f].second;
    const glm::dvec3 c(p.px[i], p.py[i], p.pz[i]);
    const double k = double(p.density[i]) * p.opacity[i], own = k * p.radius[i];
    double escape = 0.0;
    for (const ShadowRayIndex& index : outward)
      escape += std::exp(-std::max(index.optical_depth_to_light(c) - own, 0.0)) / 6.0;
    const double temperature = shading.fire_bias + shading.fire_scale * double(p.temperature[i]);
    const glm::dvec3 radiance(sample_blackbody_rgb(emission, temperature));
    out[f] = {c, radiance * sphere_opacity_area(p.radius[i], k) * escape, p.radius[i]};
  });
  return out;
}

ecs::SystemDesc fire_light_system() {
  return {.name = "fire_lights",
          .phase = ecs::Phase::light,
          .access = ecs::Access::of<ecs::Reads<ShadowSettings, RenderSettings, ExplosionShading, ParticleSet,
                                               AnisotropicCloud, ParticleLight, FlipbookFire,
                                               FlipbookEmission, FrameClock>,
                                    ecs::Writes<FireLights, FireEmissionCache>>(),
          .run = run_fire_lights,
          .setup =
              [](ecs::World& world) {
                if (!world.has_resource<FireLights>()) world.set_resource<FireLights>();
                if (!world.has_resource<FireEmissionCache>()) world.set_resource<FireEmissionCache>();
              },
          // After the shadow systems, which write the ParticleLight that shadow_casters reads.
          .after = {"shadow_rays"}};
}

}  // namespace pyro
