#pragma once
// Prewarm: start a scene as if it had already run `steps` steps of dt. Runs the
// particle emitter and animation systems for steps 0 .. steps−1 exactly as frames 0 .. steps−1
// would, then records the offset in SimulationEnvironment::prewarm_steps so that frame f
// continues as step steps + f. Deterministic: the same steps as a scene that really ran.
#include <cstdint>

namespace pyro::ecs {
class World;
}

namespace pyro {

void prewarm_particles(ecs::World& world, uint64_t steps);

}  // namespace pyro
