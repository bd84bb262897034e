#include "spin/spin_system.h"

#include <cmath>

#include "components/frame_clock.h"
#include "components/particle_set.h"
#include "engine/ecs/world.h"
#include "spin/spin.h"

namespace spin {

void turn_about_vertical(pyro::ParticlePool& pool, const glm::vec3& center, float radians) {
  const float c = std::cos(radians), s = std::sin(radians);
  for (std::size_t i = 0; i < pool.size(); ++i) {
    // Counter-clockwise seen from +y: x' = x cos + z sin, z' = -x sin + z cos.
    const float x = pool.px[i] - center.x, z = pool.pz[i] - center.z;
    pool.px[i] = center.x + c * x + s * z;
    pool.pz[i] = center.z - s * x + c * z;
  }
}

pyro::ecs::SystemDesc spin_system() {
  using namespace pyro;
  return {.name = "spin",
          .phase = ecs::Phase::simulate,
          .access = ecs::Access::of<ecs::Reads<Spin, FrameClock>, ecs::Writes<ParticleSet>>(),
          .run = [](ecs::World& world) {
            const FrameClock& clock = world.resource<const FrameClock>();
            if (clock.frame == 0) return;
            world.each<const Spin, ParticleSet>([&](const Spin& spin, ParticleSet& set) {
              turn_about_vertical(set.pool, spin.center, spin.radians_per_second * clock.dt);
            });
          }};
}

}  // namespace spin
