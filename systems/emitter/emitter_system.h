#pragma once
// Spawn phase: every Emitter spawns into its entity's ParticleSet what its rate and bursts ask
// for up to the current scene time t = (frame + prewarm steps) · dt. Counting is by absolute
// time (after t, floor(rate · (t − start)) rate particles in all), so fractions carry over
// exactly and the count never drifts; the stream's n-th particle is born at start + n / rate, as
// old as the time since, which the animation system's next step adds to its own (a stream shows
// no bands a step apart). Budgets: an emitter never holds more than its `budget`
// live particles, nor the scene more than SimulationEnvironment::particle_budget; refused spawns
// are counted (Emitter::over_budget, SimulationEnvironment::over_budget) and draw no random
// numbers. Emitters run in entity order, one stream each: deterministic for any thread count.
#include <cstdint>

#include "engine/ecs/schedule.h"

namespace pyro {

struct Emitter;
class ParticlePool;

// Spawns what `e` owes up to time t into `pool`; `scene_room` is how many more live particles
// the scene may hold (decremented per spawn). Returns how many were spawned.
uint64_t emit_until(Emitter& e, ParticlePool& pool, double t, uint64_t& scene_room,
                    uint64_t* scene_refused = nullptr);

// The `emitter` system (spawn phase, after cloud_emitter).
ecs::SystemDesc emitter_system();

}  // namespace pyro
