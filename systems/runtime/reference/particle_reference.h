#pragma once
// CPU ground truth for a particle set: the exact sum of Gaussians, integrated in closed form.
//
// Particle i (centre c, radius r, density rho, colour col) is a cube-clamped Gaussian extinction
// field whose optical depth along any ray is in closed form (engine/math/gaussian_line_integral.h).
// The ray is cut at every particle's entry, exit and closest approach; each piece is split until
// its optical depth is at most `max_piece_depth`; each piece adds T (1 - exp(-dtau)) times the
// dtau-weighted mean colour and multiplies T by exp(-dtau). Optical depth is exact; the colour
// mixing is exact for one colour and converges as pieces shrink.
// (The cutting and mixing are ray_pieces.h, shared with anisotropic_reference.h.)
#include <vector>

#include "components/volume_medium.h"
#include "engine/math/camera_math.h"
#include "engine/math/gaussian_line_integral.h"
#include "engine/particles/particle_pool.h"
#include "systems/runtime/reference/ray_pieces.h"
#include "systems/runtime/reference/rgb_image.h"

namespace pyro {

// Optical depth of one particle along the ray o + t w over t in [a, b] (closed form above).
double particle_optical_depth(const glm::dvec3& centre, double radius, double density,
                              const glm::dvec3& o, const glm::dvec3& w, double a, double b);

// The ray eye + t w's pieces (ray_pieces.h), cleared first: every particle of `gs` it meets in
// [0, t_stop], by its index in gs.
void add_particle_pieces(const std::vector<ClampedGaussian>& gs, const glm::dvec3& eye,
                         const glm::dvec3& w, double t_stop, RayPieces& pieces);

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
