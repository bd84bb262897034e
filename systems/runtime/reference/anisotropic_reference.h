#pragma once
// CPU ground truth for a set of anisotropic Gaussian particles (engine/particles/
// anisotropic_gaussian.h): each pixel's ray from the eye (t >= 0) through the sum of their
// extinction fields, every particle's optical depth in closed form
// (engine/math/anisotropic_optical_depth.h) and the colours mixed piece by piece along the ray
// (ray_pieces.h, as particle_reference.h does for the isotropic particles). Only particles whose
// projected ellipsoid (engine/math/projected_ellipsoid.h) covers a pixel are visited there.
// A particle's emission (a fire's L_e) is added unlit, weighted like its own opacity
// (ray_pieces.h), in every function below, as the splats add it.
#include <vector>

#include <glm/vec3.hpp>

#include "engine/math/camera_math.h"
#include "engine/particles/anisotropic_gaussian.h"
#include "systems/runtime/reference/lit_particle_reference.h"  // ReferenceSun
#include "systems/runtime/reference/rgb_image.h"

namespace pyro {

// `camera` must be a frame made by make_camera_frame (a symmetric perspective: the pixel rays of
// pixel_ray.h). threads = 0: hardware concurrency; the image does not depend on it.
RgbImage render_anisotropic_reference(const std::vector<AnisotropicGaussian>& particles,
                                      const CameraFrame& camera, const glm::dvec3& background,
                                      int threads = 0, double max_piece_depth = 0.02);

// The same over `behind` (an opaque scene's image), each pixel's ray cut at `stop` (its distance
// to the opaque surface; infinity: none).
RgbImage render_anisotropic_reference_over(const std::vector<AnisotropicGaussian>& particles,
                                           const CameraFrame& camera, const RgbImage& behind,
                                           const std::vector<float>& stop, int threads = 0,
                                           double max_piece_depth = 0.02);

// The particles lit (their colours are albedos) as lit_particle_reference.h lights isotropic ones:
// each part of a pixel's ray scatters its particles' mean albedo times
//   L(x) = sun.color S(mu, tau_sun(x)) + sun.ambient
// at its midpoint x, tau_sun the exact optical depth of every particle from x toward the sun (their
// closed forms, through engine/math/shadow_ray_index.h). The sun's point lights are not used.
RgbImage render_lit_anisotropic_reference_over(const std::vector<AnisotropicGaussian>& particles,
                                               const CameraFrame& camera, const ReferenceSun& sun,
                                               const RgbImage& behind, const std::vector<float>& stop,
                                               int threads = 0, double max_piece_depth = 0.02);

// The particles as shadow casters (their ellipsoids), for shadowed_opaque_reference.
std::vector<ShadowCaster> anisotropic_casters(const std::vector<AnisotropicGaussian>& particles);

}  // namespace pyro
