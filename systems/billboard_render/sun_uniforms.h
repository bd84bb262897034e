#pragma once
// The sun's uniforms of the lit splat programs (content/shaders/billboard.frag LIT and
// anisotropic_splat.frag LIT): u_toward_sun, u_sun_color, u_ambient, u_self_shadow, and through
// sun_scattering.glsl u_octaves and u_scattering. The program must be in use.
#include <glm/vec3.hpp>

#include "engine/gpu/gl_objects.h"
#include "engine/math/scattering_octaves.h"

namespace pyro {

void set_sun_uniforms(const gpu::Program& program, const glm::vec3& toward_sun, const glm::vec3& sun_color,
                      const glm::vec3& ambient, bool self_shadow, const SunScattering& scattering);

}  // namespace pyro
