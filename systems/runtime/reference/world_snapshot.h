#pragma once
// What the CPU reference (particle_reference.h) needs from a running engine: every particle
// set of a world gathered into one pool, and a rendered frame as an RGB image to compare with.
#include "components/frame_image.h"
#include "engine/ecs/world.h"
#include "engine/particles/particle_pool.h"
#include "systems/runtime/reference/rgb_image.h"

namespace pyro {

// Every live particle of every ParticleSet in `world` (position, radius, density, colour), in
// the world's order.
ParticlePool gather_particles(ecs::World& world);

// The linear RGB channels of a read-back frame (alpha dropped).
RgbImage rgb_of(const FrameImage& image);

}  // namespace pyro
