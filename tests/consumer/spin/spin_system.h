#pragma once
// The consumer's own system: turns every ParticleSet that has a Spin by the Spin's rate times
// the frame's time step, in the simulate phase (frame 0 shows the state as built, like the
// engine's own animation systems).
#include <glm/vec3.hpp>

#include "engine/ecs/schedule.h"
#include "engine/particles/particle_pool.h"

namespace spin {

// Turns the pool's live particles by `radians` about the vertical axis through `center`.
void turn_about_vertical(pyro::ParticlePool& pool, const glm::vec3& center, float radians);

pyro::ecs::SystemDesc spin_system();

}  // namespace spin
