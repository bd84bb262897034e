#pragma once
// CPU ground truth for a particle set: the exact sum of Gaussians, integrated in closed form.
//
// Particle i (centre c, radius r, density rho, colour col) is the extinction field
//   sigma_i(p) = k_i exp(-|p - c|^2 / (2 s^2)),  s = r / 3,
// clamped to the cube |p - c|_inf <= 3 s (engine/math/footprint.h: the kernel is clamped to
// [-3, 3] on every axis), with k_i chosen so that the optical depth through the centre is
// tau0 = -ln(1 - rho): the splat's opacity at its centre, 1 - exp(-tau0) = rho, is matched.
// Along a ray o + t w (|w| = 1) its optical depth over [a, b] is, with tc the closest approach
// and d the miss distance (Abramowitz & Stegun 7.1.1):
//   k exp(-d^2 / (2 s^2)) s sqrt(pi / 2) [erf((b - tc) / (s sqrt 2)) - erf((a - tc) / (s sqrt 2))].
// The ray is cut at every particle's entry, exit and closest approach; each piece is split until
// its optical depth is at most `max_piece_depth`; each piece adds T (1 - exp(-dtau)) times the
// dtau-weighted mean colour and multiplies T by exp(-dtau). Optical depth is exact; the colour
// mixing is exact for one colour and converges as pieces shrink.
// (The cutting and mixing are ray_pieces.h, shared with anisotropic_reference.h.)
#include <vector>

#include "components/volume_medium.h"
#include "engine/math/camera_math.h"
#include "engine/particles/particle_pool.h"
#include "systems/reference/rgb_image.h"

namespace pyro {

// Optical depth of one particle along the ray o + t w over t in [a, b] (closed form above).
double particle_optical_depth(const glm::dvec3& centre, double radius, double density,
                              const glm::dvec3& o, const glm::dvec3& w, double a, double b);

RgbImage render_particles_reference(const ParticlePool& particles, const CameraFrame& camera,
                                    const glm::dvec3& background, int threads = 0,
                                    double max_piece_depth = 0.02);

// The same particles in front of an opaque scene: `behind` (linear RGB, camera size) is what each
// pixel's ray meets after the medium, at distance `stop` along the ray (infinity: nothing), so
// particles are cut where the surface is, as the GL renderer's depth test cuts them.
RgbImage render_particles_reference_over(const ParticlePool& particles, const CameraFrame& camera,
                                         const RgbImage& behind, const std::vector<float>& stop,
                                         int threads = 0, double max_piece_depth = 0.02);

// Distances along each pixel's ray (camera.width x camera.height, top row first) to the surface
// whose GL window depth (glm::perspective, depth range [0, 1]) is `depth`; 1 gives infinity.
std::vector<float> ray_stop_distances(const CameraFrame& camera, const std::vector<float>& depth);

}  // namespace pyro
