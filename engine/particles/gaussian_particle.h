#pragma once
// One Gaussian particle as stored in a particle file and made by the cloud importer: the same
// fields the billboard pass draws (engine/math/footprint.h: radius is 3 sigma; density rho is
// the opacity at the centre; colour is linear RGB, lighting already applied).
namespace pyro {

struct GaussianParticle {
  float x = 0, y = 0, z = 0;
  float radius = 1;
  float density = 0;
  float r = 1, g = 1, b = 1;
};
static_assert(sizeof(GaussianParticle) == 32, "the particle file stores 8 floats per particle");

}  // namespace pyro
