#include "systems/billboard_render/sun_uniforms.h"

#include <glm/gtc/type_ptr.hpp>

#include "engine/gpu/shader_program.h"

namespace pyro {

void set_sun_uniforms(const gpu::Program& program, const glm::vec3& toward_sun, const glm::vec3& sun_color,
                      const glm::vec3& ambient, bool self_shadow, const SunScattering& scattering) {
  glUniform3fv(gpu::uniform_location(program, "u_toward_sun"), 1, glm::value_ptr(toward_sun));
  glUniform3fv(gpu::uniform_location(program, "u_sun_color"), 1, glm::value_ptr(sun_color));
  glUniform3fv(gpu::uniform_location(program, "u_ambient"), 1, glm::value_ptr(ambient));
  glUniform1f(gpu::uniform_location(program, "u_self_shadow"), self_shadow ? 1.0f : 0.0f);
  const ScatteringOctaves& o = scattering.octaves;
  glUniform1i(gpu::uniform_location(program, "u_octaves"), o.octaves);
  glUniform4f(gpu::uniform_location(program, "u_scattering"), float(scattering.anisotropy), float(o.attenuation),
              float(o.contribution), float(o.eccentricity));
}

}  // namespace pyro
