#include "systems/emitter/cloud_emitter_system.h"

#include <cmath>
#include <numbers>

#include "components/cloud_volume.h"
#include "components/particle_set.h"
#include "engine/core/rng.h"
#include "engine/ecs/world.h"

namespace pyro {

void fill_cloud(const CloudVolume& c, ParticleSet& set) {
  Rng rng(c.seed);
  set.pool.clear();
  for (uint32_t k = 0; k < c.count; ++k) {
    ParticleInit p;
    p.position = {rng.uniform(c.box_min.x, c.box_max.x), rng.uniform(c.box_min.y, c.box_max.y),
                  rng.uniform(c.box_min.z, c.box_max.z)};
    // Jitter: a uniformly random direction (Marsaglia-free: z uniform, angle uniform).
    const float z = rng.uniform(-1.0f, 1.0f);
    const float a = rng.uniform(0.0f, 2.0f * std::numbers::pi_v<float>);
    const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
    p.velocity = c.drift + c.jitter * glm::vec3(s * std::cos(a), s * std::sin(a), z);
    p.radius = c.radius;
    p.density = c.density;
    p.color = c.color;
    if (!set.pool.spawn(p)) break;  // capacity reached: the pool counts the rejects
  }
}

ecs::SystemDesc cloud_emitter_system() {
  return {.name = "cloud_emitter",
          .phase = ecs::Phase::spawn,
          .access = ecs::Access::of<ecs::Writes<CloudVolume, ParticleSet>>(),
          .run = [](ecs::World& world) {
            world.each<CloudVolume, ParticleSet>([](CloudVolume& c, ParticleSet& s) {
              if (c.filled) return;
              fill_cloud(c, s);
              c.filled = true;
            });
          }};
}

}  // namespace pyro
