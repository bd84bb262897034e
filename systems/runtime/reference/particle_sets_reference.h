#pragma once
// CPU ground truth for particle sets of different kinds in one image (components/particle_kind.h):
// every particle of every set is a field of extinction along each pixel's ray, and the ray is
// integrated through all of them at once (ray_pieces.h), so particles of different kinds that
// overlap in depth mix exactly where they overlap.
//  - Gaussian: as particle_reference.h (the cube-clamped Gaussian whose centre opacity is the
//    particle's density), optical depth in closed form.
//  - spherical: a sphere of the particle's radius (Umenhoffer et al. 2006, eq. 2) whose extinction
//    along a ray passing at distance d from its centre is tau (1 - d/r) over the chord, tau the
//    particle's density (engine/math/sphere_line_integral.h): what the spherical billboard's
//    fragment shader integrates.
// Planar billboards approximate the spherical particle (no field of their own): refused.
#include <vector>

#include "components/render_modes.h"
#include "engine/math/camera_math.h"
#include "engine/particles/particle_pool.h"
#include "systems/runtime/reference/rgb_image.h"

namespace pyro {

struct ReferenceParticleSet {
  const ParticlePool* pool = nullptr;
  ParticleShape shape = ParticleShape::gaussian;
};

// Throws std::invalid_argument for a planar set.
RgbImage render_particle_sets_reference(const std::vector<ReferenceParticleSet>& sets,
                                        const CameraFrame& camera, const glm::dvec3& background,
                                        int threads = 0, double max_piece_depth = 0.02);

}  // namespace pyro
