#pragma once
// How an emitter's particles move and change over their life (systems/animation): forces,
// cooling, fire-to-smoke, curves over life and collision response. Scene-wide quantities
// (gravity, wind, ambient temperature, colliders) are in the SimulationEnvironment resource.
#include <cstdint>

#include "components/life_curve.h"

namespace pyro {

struct ParticleDynamics {
  float gravity_scale = 1.0f;       // × environment gravity
  // Boussinesq buoyancy: a = buoyancy · (T − T_ambient) along +y (units m s⁻² K⁻¹).
  float buoyancy = 0.0f;
  float drag = 0.0f;                // k in dv/dt = −k (v − w), 1/s; w = wind + turbulence
  // Curl-noise turbulence (Bridson et al. 2007): a divergence-free velocity added to the wind,
  // amplitude × curl ψ(frequency · x + time · drift), ψ a smooth 3D noise potential.
  float turbulence = 0.0f;          // m / s
  float turbulence_frequency = 0.5f;  // 1 / m
  float turbulence_speed = 0.3f;    // how fast the noise pattern moves, 1/s in noise units
  uint64_t turbulence_seed = 7;
  float cooling = 0.0f;             // k in dT/dt = −k (T − T_ambient), 1/s (Newton)
  float smoke_below = 0.0f;         // fire particles cooler than this (K) become smoke
  // Curves over life; empty = not used. size multiplies the birth radius; opacity sets
  // ParticlePool::opacity; temperature (K) replaces cooling; color sets r, g, b.
  LifeCurve size, opacity, temperature, color;
  // Collisions with the environment's ground and shapes: the normal velocity is reversed and
  // scaled by restitution, the tangential one scaled by (1 − friction).
  bool collide = true;
  float restitution = 0.3f;
  float friction = 0.2f;
};

}  // namespace pyro
