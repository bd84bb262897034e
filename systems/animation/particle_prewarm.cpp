#include "systems/animation/particle_prewarm.h"

#include "components/frame_clock.h"
#include "components/simulation_environment.h"
#include "engine/ecs/world.h"
#include "systems/animation/particle_animation_system.h"
#include "systems/emitter/emitter_system.h"

namespace pyro {

void prewarm_particles(ecs::World& world, uint64_t steps) {
  FrameClock& clock = world.resource<FrameClock>();
  SimulationEnvironment& env = world.resource<SimulationEnvironment>();
  const uint64_t frame = clock.frame;
  env.prewarm_steps = 0;
  const ecs::SystemDesc emit = emitter_system();
  const ecs::SystemDesc animate = animation_system();
  for (uint64_t g = 0; g < steps; ++g) {
    clock.frame = g;
    emit.run(world);
    animate.run(world);
  }
  clock.frame = frame;
  env.prewarm_steps = steps;
}

}  // namespace pyro
