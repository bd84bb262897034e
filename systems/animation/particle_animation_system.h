#pragma once
// Simulate phase for emitter particles (components/emitter.h, components/particle_dynamics.h):
// gravity, Boussinesq buoyancy a = β (T − T_amb) ŷ, drag toward the wind plus curl-noise
// turbulence, Newtonian cooling with fire turning to smoke, curves over life, collisions with
// the environment's ground, spheres and boxes, then ageing and removal at the end of life
// (ParticlePool::kill_if, so survivors keep their order). Integration: the exponential
// integrator of particle_integrator.h. Frame 0 shows the emitted state, like the cloud drift.
#include <cstddef>

#include <glm/vec3.hpp>

#include "engine/ecs/schedule.h"

namespace pyro {

struct ParticleDynamics;
struct SimulationEnvironment;
class ParticlePool;

// One step of dt at scene time `time` (seconds; moves the turbulence pattern). Returns how many
// particles reached the end of their life and were removed.
std::size_t animate_particles(ParticlePool& pool, const ParticleDynamics& d,
                              const SimulationEnvironment& env, float dt, double time);

// Pushes a point out of the environment's colliders and reflects its velocity (restitution,
// friction); true if it touched something.
bool collide_particle(glm::vec3& x, glm::vec3& v, const SimulationEnvironment& env, float restitution,
                      float friction);

// The `animation` system (simulate phase, after cloud_drift).
ecs::SystemDesc animation_system();

}  // namespace pyro
