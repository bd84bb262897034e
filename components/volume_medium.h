#pragma once
// How a density grid or a particle set interacts with light, shared by the CPU reference and
// the importer's lighting. Emission-absorption with single scattering from one directional light
// (Max 1995, "Optical models for direct volume rendering", sections 2-4): the extinction
// coefficient is sigma_t(p) = extinction * density(p) per world unit, and the source term is
//   S(p) = albedo * (light_color * exp(-tau_light(p)) + ambient),
// with an isotropic phase function whose 1/(4 pi) is folded into light_color, so that a fully lit
// particle of albedo 1 shows the light's colour. tau_light(p) is the optical depth from p to the
// light along -light_direction (self-shadowing).
#include <glm/vec3.hpp>

namespace pyro {

struct VolumeMedium {
  double extinction = 1.0;                   // per world unit per unit density
  double albedo = 0.9;                       // sigma_s / sigma_t
  glm::dvec3 light_direction{-0.4, -1.0, -0.3};  // direction the light travels (normalised on use)
  glm::dvec3 light_color{1.0, 1.0, 1.0};
  glm::dvec3 ambient{0.25, 0.27, 0.32};
  glm::dvec3 background{0.62, 0.68, 0.76};   // linear RGB behind the volume
};

}  // namespace pyro
