#pragma once
// The defaults of an emitter's keys that depend on what it emits (emitters[].medium): smoke and
// fire are hot gas and rise, dust is grains and falls. The loader applies them after reading
// "medium" and before the other keys, so any key written in the scene wins.
//
// Hot gas, smoke and fire:
//  - temperature at birth: smoke 373 K (a chimney's flue gas, 80 K above the default ambient
//    293 K), fire 1500 K (a wood or hydrocarbon flame's body);
//  - buoyancy beta = |g| / T_birth: the Boussinesq form a = beta (T - T_amb) up
//    (components/particle_dynamics.h) then equals, at the birth temperature, the exact buoyancy
//    of an ideal gas at the air's pressure, a = g (rho_amb - rho) / rho_amb = g (T - T_amb) / T
//    (Archimedes with rho proportional to 1/T): smoke 9.81 / 373, fire 9.81 / 1500;
//  - gravity_scale 0: that buoyancy is already the net of the parcel's weight and the air's lift;
//  - drag 1/s: a parcel of gas is carried by the air around it; its speed relaxes to the wind
//    within about a second, so a plume rises at about beta (T - T_amb) / drag (smoke: 2.1 m/s).
// Dust keeps the plain-data defaults (components/emitter.h, particle_dynamics.h): 0 K, full
// gravity, no buoyancy, no drag.
#include "components/emitter.h"
#include "components/particle_dynamics.h"

namespace pyro {

// Overwrites the medium-dependent fields of `emitter` and `dynamics` with `medium`'s defaults.
void apply_medium_defaults(ParticleMedium medium, Emitter& emitter, ParticleDynamics& dynamics);

}  // namespace pyro
