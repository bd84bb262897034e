#pragma once
// How many particles a world holds and draws, for reports (pyro render, profile, view, the
// benchmarks): one place that knows where particles live (ParticleSet pools, one per cloud,
// volume or emitter; AnisotropicCloud components for fitted volumes) and where the drawn ones are
// listed (the sorted EyeDrawLists, or the GPU's order when it made it).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "engine/ecs/world.h"

namespace pyro {

// Particles the last frame drew in the first view (its draw list, the GPU's kept count when the
// GPU ordered it, and every anisotropic particle); 0 before any frame.
size_t drawn_particles(ecs::World& world);

struct ParticleSourceCount {
  std::string name;  // the emitter's name, "particle set K" for a cloud or volume, or
                     // "anisotropic cloud K" for a fitted volume
  uint64_t live = 0, capacity = 0;
};

struct ParticleCensus {
  uint64_t live = 0, capacity = 0;  // over every pool
  std::vector<ParticleSourceCount> sources;  // per pool, in entity order
  std::map<std::string, uint64_t> by_medium;  // emitters' live particles per medium name
};

ParticleCensus count_particles(ecs::World& world);

// count_particles(world).live.
uint64_t live_particles(ecs::World& world);

}  // namespace pyro
