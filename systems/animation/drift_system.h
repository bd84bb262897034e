#pragma once
// Simulate phase: cloud particles drift with their velocity and wrap around inside their box
// (a periodic volume, so a drifting fog bank keeps its density); the camera follows its orbit.
#include "engine/ecs/schedule.h"

namespace pyro {

struct CloudVolume;
struct ParticleSet;

// One explicit step: exact for constant velocity, so no integrator error accrues.
void drift_particles(const CloudVolume& cloud, ParticleSet& set, float dt);
// The `cloud_drift` and `camera_orbit` systems.
ecs::SystemDesc cloud_drift_system();
ecs::SystemDesc camera_orbit_system();

}  // namespace pyro
