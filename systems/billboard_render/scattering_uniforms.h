#pragma once
// The lit splat programs' own uniforms (content/shaders/billboard.frag LIT and
// anisotropic_splat.frag LIT): u_self_shadow, and through sun_scattering.glsl u_octaves and
// u_scattering. Their lights come from the light block (lights.glsl). The program must be in use.
#include "engine/gpu/gl_objects.h"
#include "engine/math/scattering_octaves.h"

namespace pyro {

void set_scattering_uniforms(const gpu::Program& program, bool self_shadow, const SunScattering& scattering);

}  // namespace pyro
