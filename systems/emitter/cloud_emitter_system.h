#pragma once
// Spawn phase: fills each CloudVolume's ParticleSet with `count` particles at uniformly random
// positions in its box (Johnson & McAllister 2005, section 4), once. Deterministic per seed.
#include "engine/ecs/schedule.h"

namespace pyro {

struct CloudVolume;
struct ParticleSet;

void fill_cloud(const CloudVolume& cloud, ParticleSet& set);
// The `cloud_emitter` system.
ecs::SystemDesc cloud_emitter_system();

}  // namespace pyro
