#include "systems/scene_runtime/particle_counts.h"

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
    if (emitter)
      for (size_t i = 0; i < set.pool.size(); ++i)
        census.by_medium[std::string(name_of(static_cast<ParticleMedium>(set.pool.medium[i])))] += 1;
  });
  return census;
}

uint64_t live_particles(ecs::World& world) { return count_particles(world).live; }

}  // namespace pyro
