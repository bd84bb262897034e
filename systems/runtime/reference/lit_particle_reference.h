#pragma once
// CPU ground truth for lit particle media with shadows: single scattering of one sun through the
// particles, with the sun's transmittance exact at every point (docs/lighting.md).
//
// Along each pixel ray the particles are integrated as in particle_reference.h; each part of the
// ray (of optical depth at most `max_piece_depth`) scatters its particles' mean albedo times
//   L(x) = sun_color S(mu, tau_sun(x)) + ambient,
// x the part's midpoint and tau_sun(x) the exact optical depth of every particle from x toward the
// sun (the closed-form line integrals, engine/math/shadow_ray_index.h), S the sun's scattering
// towards the eye (engine/math/scattering_octaves.h; one isotropic octave: exp(-tau)). The
// engine's light phase evaluates L once per particle, at its centre; this evaluates it along the
// rays, so it measures that shortcut and the shadow method together.
//
// Opaque surfaces: the GL render of the opaque scene with the sun (`sunlit`) and without it
// (`sunless`) give each pixel's sun term, sunlit - sunless; the surface point the pixel's ray
// meets (at `stop`) keeps exp(-tau_sun) of it.
#include <functional>
#include <vector>

#include "engine/math/camera_math.h"
#include "engine/math/point_light_clusters.h"
#include "engine/math/scattering_octaves.h"
#include "engine/math/shadow_caster.h"
#include "engine/particles/particle_pool.h"
#include "systems/runtime/reference/rgb_image.h"

namespace pyro {

struct ReferenceSun {
  glm::dvec3 travel{0.0, -1.0, 0.0};  // the direction the sunlight travels (not zero)
  glm::dvec3 color{1.0};              // sun colour times intensity
  glm::dvec3 ambient{0.0};
  SunScattering scattering;  // the particles' phase lobe and octaves; the surfaces see exp(-tau)
  // Point lights (the fire's, components/fire_lights.h): each adds I p_HG(mu, g) / max(d^2, r^2)
  // to L(x), mu between its light's way at x and the way to the eye. Unshadowed, as the splats'.
  std::vector<PointEmitter> point_lights;
  // The meshes' shadow as an optical depth toward the sun at a point in a medium, and at a point
  // on a surface (a larger bias: the surface may be a caster's own face), added to the
  // particles' (the light phase's mesh shadow grid, systems/shadowing/mesh_shadow_map.h); none:
  // no meshes cast.
  std::function<double(const glm::dvec3&)> mesh_depth, mesh_surface_depth;

  double mesh_depth_at(const glm::dvec3& p) const { return mesh_depth ? mesh_depth(p) : 0.0; }
  double mesh_surface_depth_at(const glm::dvec3& p) const { return mesh_surface_depth ? mesh_surface_depth(p) : 0.0; }
};

// The opaque scene with the media's shadows: sunless + exp(-tau_sun(p)) (sunlit - sunless), p the
// point at distance `stop` along each pixel's ray (none: the pixel is left as sunlit).
RgbImage shadowed_opaque_reference(const ParticlePool& particles, const CameraFrame& camera,
                                   const ReferenceSun& sun, const RgbImage& sunlit,
                                   const RgbImage& sunless, const std::vector<float>& stop,
                                   int threads = 0);
// The same with the media's shadows cast by `casters`.
RgbImage shadowed_opaque_reference(std::vector<ShadowCaster> casters, const CameraFrame& camera,
                                   const ReferenceSun& sun, const RgbImage& sunlit,
                                   const RgbImage& sunless, const std::vector<float>& stop,
                                   int threads = 0);

// The lit particles (the pool's colours are their albedos) over `behind`, cut at `stop`.
RgbImage render_lit_particles_reference_over(const ParticlePool& particles, const CameraFrame& camera,
                                             const ReferenceSun& sun, const RgbImage& behind,
                                             const std::vector<float>& stop, int threads = 0,
                                             double max_piece_depth = 0.02);

}  // namespace pyro
