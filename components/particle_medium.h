#pragma once
// What a particle is a sample of (Umenhoffer et al. 2006, section 3): dust and smoke scatter
// light (albedo a, density τ, a phase function), fire emits as a black body. Stored per particle
// in ParticlePool::medium, so a fire particle that cools below its emitter's threshold becomes
// smoke in place.
#include "engine/core/enum_names.h"
#include <cstdint>

namespace pyro {

enum class ParticleMedium : uint8_t { dust = 0, smoke = 1, fire = 2 };
inline constexpr EnumName<ParticleMedium> particle_medium_names[] = {
    {ParticleMedium::dust, "dust"}, {ParticleMedium::smoke, "smoke"}, {ParticleMedium::fire, "fire"}};
constexpr const auto& enum_names(ParticleMedium) { return particle_medium_names; }

}  // namespace pyro
