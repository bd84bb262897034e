#include "systems/runtime/scene_runtime/particle_counts.h"

#include <array>

#include "components/anisotropic_cloud.h"
#include "components/draw_list.h"
#include "components/emitter.h"
#include "components/particle_medium.h"
#include "components/particle_set.h"
#include "engine/core/enum_names.h"
#include "systems/billboard_render/billboard_renderer.h"

namespace pyro {

namespace {

// Anisotropic clouds (a version 2 particle file) live outside the pools and are drawn whole in
// every view.
uint64_t anisotropic_particles(ecs::World& world) {
  uint64_t n = 0;
  world.each<const AnisotropicCloud>([&](const AnisotropicCloud& c) { n += c.particles.size(); });
  return n;
}

}  // namespace

size_t drawn_particles(ecs::World& world) {
  const auto* lists = world.try_resource<EyeDrawLists>();
  if (!lists || lists->eyes.empty()) return 0;  // no frame drawn yet
  const DrawList& first = lists->eyes[0];
  size_t drawn = first.size();
  if (first.on_gpu) {  // ordered and culled on the GPU: the CPU's list is empty
    const BillboardRenderer* renderer = world.try_resource<BillboardRenderer>();
    drawn = renderer ? renderer->gpu_kept() : 0;
  }
  return drawn + anisotropic_particles(world);
}

ParticleCensus count_particles(ecs::World& world) {
  ParticleCensus census;
  size_t set_index = 0;
  world.each<ParticleSet>([&](ecs::Entity e, ParticleSet& set) {
    const Emitter* emitter = world.try_get<Emitter>(e);
    const std::string name = emitter ? emitter->name : "particle set " + std::to_string(set_index);
    ++set_index;
    census.sources.push_back({name, set.pool.size(), set.pool.capacity()});
    census.live += set.pool.size();
    census.capacity += set.pool.capacity();
    if (!emitter) return;
    // Per medium byte first, then one name per medium present.
    std::array<uint64_t, 256> by_byte{};
    for (size_t i = 0; i < set.pool.size(); ++i) ++by_byte[set.pool.medium[i]];
    for (size_t m = 0; m < by_byte.size(); ++m)
      if (by_byte[m] > 0)
        census.by_medium[std::string(name_of(static_cast<ParticleMedium>(m)))] += by_byte[m];
  });
  size_t cloud_index = 0;
  world.each<const AnisotropicCloud>([&](const AnisotropicCloud& c) {
    const uint64_t n = c.particles.size();
    census.sources.push_back({"anisotropic cloud " + std::to_string(cloud_index++), n, n});
    census.live += n;
    census.capacity += n;
  });
  return census;
}

uint64_t live_particles(ecs::World& world) {
  uint64_t live = 0;
  world.each<ParticleSet>([&](ecs::Entity, ParticleSet& set) { live += set.pool.size(); });
  return live + anisotropic_particles(world);
}

}  // namespace pyro
