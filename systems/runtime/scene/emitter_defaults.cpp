#include "systems/runtime/scene/emitter_defaults.h"

namespace pyro {

namespace {

constexpr float kStandardGravity = 9.81f;  // m s^-2, the environment's default |gravity|
constexpr float kSmokeBirthKelvin = 373.0f;
constexpr float kFireBirthKelvin = 1500.0f;
constexpr float kGasDragPerSecond = 1.0f;

void hot_gas_defaults(float birth_kelvin, Emitter& emitter, ParticleDynamics& dynamics) {
  emitter.temperature = Distribution::constant(birth_kelvin);
  dynamics.gravity_scale = 0.0f;
  dynamics.buoyancy = kStandardGravity / birth_kelvin;
  dynamics.drag = kGasDragPerSecond;
}

}  // namespace

void apply_medium_defaults(ParticleMedium medium, Emitter& emitter, ParticleDynamics& dynamics) {
  const Emitter plain_emitter;
  const ParticleDynamics plain_dynamics;
  switch (medium) {
    case ParticleMedium::smoke:
      hot_gas_defaults(kSmokeBirthKelvin, emitter, dynamics);
      return;
    case ParticleMedium::fire:
      hot_gas_defaults(kFireBirthKelvin, emitter, dynamics);
      return;
    case ParticleMedium::dust:
      break;
  }
  emitter.temperature = plain_emitter.temperature;
  dynamics.gravity_scale = plain_dynamics.gravity_scale;
  dynamics.buoyancy = plain_dynamics.buoyancy;
  dynamics.drag = plain_dynamics.drag;
}

}  // namespace pyro
