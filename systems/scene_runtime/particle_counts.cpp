#include "systems/scene_runtime/particle_counts.h"

#include <array>

#include "components/draw_list.h"
#include "components/emitter.h"
#include "components/particle_medium.h"
#include "components/particle_set.h"
#include "engine/core/enum_names.h"

namespace pyro {

size_t drawn_particles(ecs::World& world) {
  const auto* lists = world.try_resource<EyeDrawLists>();
  return lists && !lists->eyes.empty() ? lists->eyes[0].size() : 0;
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
  return census;
}

uint64_t live_particles(ecs::World& world) {
  uint64_t live = 0;
  world.each<ParticleSet>([&](ecs::Entity, ParticleSet& set) { live += set.pool.size(); });
  return live;
}

}  // namespace pyro
