#include "systems/emitter/emitter_system.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "components/emitter.h"
#include "components/frame_clock.h"
#include "components/particle_set.h"
#include "components/simulation_environment.h"
#include "engine/ecs/world.h"
#include "engine/math/value_noise.h"
#include "systems/emitter/emitter_sampling.h"

namespace pyro {

namespace {

// A birth point on the shape where the pattern is on at time t (components/emitter.h).
glm::vec3 birth_point(Emitter& e, double t) {
  glm::vec3 p = sample_shape(e, e.rng);
  const EmitterPattern& pattern = e.pattern;
  if (!(pattern.frequency > 0.0f)) return p;
  const glm::vec3 drift = glm::vec3(0.37f, 0.81f, 0.45f) * static_cast<float>(t * pattern.speed);
  glm::vec3 best = p;
  float best_value = -2.0f;
  for (int i = 0; i < kPatternTries; ++i) {
    if (i > 0) p = sample_shape(e, e.rng);
    const float n = value_noise(p * pattern.frequency + drift, e.seed ^ 0x5bd1e995u);
    if (n >= pattern.threshold) return p;
    if (n > best_value) best_value = n, best = p;
  }
  return best;
}

ParticleInit sample_particle(Emitter& e, double birth) {
  Rng& rng = e.rng;
  ParticleInit p;
  p.position = birth_point(e, birth);
  glm::vec3 dir = sample_cone(e.direction, e.cone_deg, rng);  // always drawn: fixed stream use
  if (e.radial) {
    const glm::vec3 out = p.position - e.position;
    const float len = glm::length(out);
    dir = len > 1e-6f ? out / len : sample_cone(e.direction, 180.0f, rng);
  }
  p.velocity = sample_distribution(e.speed, rng) * dir;
  p.radius = std::max(sample_distribution(e.size, rng), 1e-6f);
  p.lifetime = std::max(sample_distribution(e.lifetime, rng), 1e-6f);
  p.density = std::max(sample_distribution(e.density, rng), 0.0f);
  p.temperature = std::max(sample_distribution(e.temperature, rng), 0.0f);
  p.color = e.color;
  p.opacity = 1.0f;
  p.medium = static_cast<uint8_t>(e.medium);
  return p;
}

}  // namespace

uint64_t emit_until(Emitter& e, ParticlePool& pool, double t, uint64_t& scene_room,
                    uint64_t* scene_refused) {
  uint64_t bursts = 0, streamed = 0;
  while (e.next_burst < e.bursts.size() && e.bursts[e.next_burst].time <= t)
    bursts += e.bursts[e.next_burst++].count;
  const uint64_t stream_first = e.rate_emitted;  // the stream's particles born before this call
  if (e.rate > 0.0f && t > e.start) {
    const double active = std::min(t - e.start, static_cast<double>(e.duration));
    const auto target = static_cast<uint64_t>(std::floor(static_cast<double>(e.rate) * active));
    if (target > e.rate_emitted) streamed = target - e.rate_emitted;
    e.rate_emitted = std::max(e.rate_emitted, target);
  }
  e.time = t;
  const std::size_t cap = std::min<std::size_t>(e.budget, pool.capacity());
  uint64_t spawned = 0;
  for (uint64_t k = 0; k < bursts + streamed; ++k) {
    if (pool.size() >= cap) {
      ++e.over_budget;
      continue;
    }
    if (scene_room == 0) {
      ++e.over_budget;
      if (scene_refused) ++*scene_refused;
      continue;
    }
    // The stream's n-th particle is born at start + n / rate, within the step: it is as old as the
    // time since, over which the animation system moves it on top of the step (a stream shows no
    // bands a step's flight apart).
    const double birth =
        k >= bursts ? e.start + static_cast<double>(stream_first + (k - bursts) + 1) / e.rate : t;
    ParticleInit p = sample_particle(e, birth);
    p.age = static_cast<float>(std::max(0.0, t - birth));
    pool.spawn(p);
    --scene_room;
    ++spawned;
  }
  e.spawned += spawned;
  return spawned;
}

ecs::SystemDesc emitter_system() {
  return {.name = "emitter",
          .phase = ecs::Phase::spawn,
          .access = ecs::Access::of<ecs::Reads<FrameClock>,
                                    ecs::Writes<Emitter, ParticleSet, SimulationEnvironment>>(),
          .run =
              [](ecs::World& world) {
                const FrameClock& clock = world.resource<const FrameClock>();
                SimulationEnvironment& env = world.resource<SimulationEnvironment>();
                const double t = static_cast<double>(clock.frame + env.prewarm_steps) * clock.dt;
                uint64_t live = 0;
                world.each<const Emitter, const ParticleSet>(
                    [&](const Emitter&, const ParticleSet& s) { live += s.pool.size(); });
                uint64_t room = live >= env.particle_budget ? 0 : env.particle_budget - live;
                world.each<Emitter, ParticleSet>([&](Emitter& e, ParticleSet& s) {
                  emit_until(e, s.pool, t, room, &env.over_budget);
                });
              },
          // Both emitters spawn into ParticleSets (of different entities; access is per type).
          .after = {"cloud_emitter"}};
}

}  // namespace pyro
