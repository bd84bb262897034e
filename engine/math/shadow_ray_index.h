#pragma once
// Particles (Gaussians or spheres, engine/math/shadow_caster.h) binned across a light's direction,
// so that the exact optical depth from any point toward the light (a shadow ray: the sum of the
// few particles' closed-form line integrals) visits only the particles the ray can meet.
//
// The bins are square cells of a plane perpendicular to the light. A particle projects inside a
// disc of its reach about its centre's projection (a Gaussian's cube, half-width 3 s: radius
// 3 s sqrt 3; a sphere: its radius); it is listed in every cell that disc's bounding square
// touches, so a ray through a cell meets no particle that the cell does not list.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/math/shadow_caster.h"

namespace pyro {

class ShadowRayIndex {
 public:
  ShadowRayIndex() = default;
  // `light_travel`: the direction the light travels (any length, not zero).
  ShadowRayIndex(std::vector<ShadowCaster> particles, const glm::dvec3& light_travel);

  // The optical depth of every particle along the ray from p toward the light, summed in the
  // particles' order (deterministic whatever the thread).
  double optical_depth_to_light(const glm::dvec3& p) const;

  const std::vector<ShadowCaster>& particles() const { return particles_; }
  std::size_t cells() const { return starts_.empty() ? 0 : starts_.size() - 1; }

 private:
  // The cell of a point's projection, or -1 outside the grid.
  long cell_of(double u, double v) const;

  std::vector<ShadowCaster> particles_;
  glm::dvec3 toward_light_{0.0, 1.0, 0.0}, u_axis_{1.0, 0.0, 0.0}, v_axis_{0.0, 0.0, 1.0};
  double u0_ = 0.0, v0_ = 0.0, cell_ = 1.0;
  int nu_ = 0, nv_ = 0;
  std::vector<uint32_t> starts_, items_;  // cell c lists items_[starts_[c] .. starts_[c + 1])
};

// Two unit vectors that make a right-handed orthonormal frame (u, v, w) with the unit vector w.
void orthonormal_basis(const glm::dvec3& w, glm::dvec3& u, glm::dvec3& v);

}  // namespace pyro
