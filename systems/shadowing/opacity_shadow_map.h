#pragma once
// Opacity shadow maps (Kim & Neumann 2001, "Opacity Shadow Maps"): the media's optical depth
// toward the light, stored on slices perpendicular to the light's direction and interpolated
// between them. Kim & Neumann render the slices by rasterising the particles; here each texel
// of each slice holds the exact sum of the particles' closed-form line integrals from the
// light's side of the media to the texel's centre (Gaussians or spheres,
// engine/math/shadow_caster.h), so the map's only error is its interpolation between texels and
// slices, which its size sets.
#include <vector>

#include <glm/vec3.hpp>

#include "components/shadow_volume.h"
#include "engine/math/shadow_caster.h"

namespace pyro {

struct ShadowMapSize {
  int across = 128;  // texels across the light on the grid's longer side, >= 4
  int slices = 64;   // slices along the light, >= 4
};

// The map of `particles` for light travelling along `light_travel` (not zero): a light-space box
// fitted to the particles with one empty texel (or slice) beyond them on every side, so that
// texture coordinates outside it read no medium across the light and the whole column past it.
// `out.version` is incremented. No particles: out is emptied.
void build_opacity_shadow_map(const std::vector<ShadowCaster>& particles,
                              const glm::dvec3& light_travel, ShadowMapSize size, ShadowVolume& out);

// The optical depth at world point p, interpolated trilinearly between texel centres and clamped
// at the edges, as GL samples the map (GL_LINEAR, GL_CLAMP_TO_EDGE). Empty map: 0.
float sample_optical_depth(const ShadowVolume& map, const glm::vec3& p);

}  // namespace pyro
