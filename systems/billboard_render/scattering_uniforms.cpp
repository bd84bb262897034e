#include "systems/billboard_render/scattering_uniforms.h"

#include "engine/gpu/shader_program.h"

namespace pyro {

void set_scattering_uniforms(const gpu::Program& program, bool self_shadow, const SunScattering& scattering) {
  glUniform1f(gpu::uniform_location(program, "u_self_shadow"), self_shadow ? 1.0f : 0.0f);
  const ScatteringOctaves& o = scattering.octaves;
  glUniform1i(gpu::uniform_location(program, "u_octaves"), o.octaves);
  glUniform4f(gpu::uniform_location(program, "u_scattering"), float(scattering.anisotropy), float(o.attenuation),
              float(o.contribution), float(o.eccentricity));
}

}  // namespace pyro
