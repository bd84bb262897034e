#pragma once
// The particles an entity owns, in structure-of-arrays storage.
#include "engine/particles/particle_pool.h"

namespace pyro {

struct ParticleSet {
  ParticlePool pool;
};

}  // namespace pyro
