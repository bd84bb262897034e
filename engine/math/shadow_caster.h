#pragma once
// A particle that casts shadows, whichever its shape: a clamped Gaussian (the splats: clouds,
// fog, mist, imported volumes; engine/math/gaussian_line_integral.h), a spherical particle of
// the explosion's billboards (engine/math/sphere_line_integral.h) or an anisotropic Gaussian
// (fitted imports; engine/math/anisotropic_optical_depth.h). The light phase's shadow maps and
// shadow rays integrate all three along a ray through the same few calls.
#include <cstdint>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "engine/math/anisotropic_optical_depth.h"
#include "engine/math/gaussian_line_integral.h"
#include "engine/math/sphere_line_integral.h"

namespace pyro {

enum class CasterShape : uint8_t { gaussian, sphere, ellipsoid };

struct ShadowCaster {
  CasterShape shape = CasterShape::gaussian;
  glm::dvec3 c{0.0};
  double size = 1.0;  // gaussian: the standard deviation s; sphere: the radius r; ellipsoid:
                      // its reach, kAnisotropicExtent times the largest scale
  double k = 0.0;     // gaussian, ellipsoid: the extinction at the centre; sphere: along a ray
                      // through it
  glm::mat3 whitening{1.0f};  // ellipsoid: M = S^-1 R^T (whitening_matrix)

  ShadowCaster() = default;
  ShadowCaster(const ClampedGaussian& g) : shape(CasterShape::gaussian), c(g.c), size(g.s), k(g.k) {}
  ShadowCaster(const ConeSphere& s) : shape(CasterShape::sphere), c(s.c), size(s.r), k(s.k) {}
  ShadowCaster(const AnisotropicGaussian& g);
  ClampedGaussian gaussian() const { return {c, size, k}; }
  ConeSphere sphere() const { return {c, size, k}; }
  // An ellipsoid's line o + t w (|w| = 1) through it.
  AnisotropicRaySegment ellipsoid(const glm::dvec3& o, const glm::dvec3& w) const;
};

// Appends the particles with extinction > 0 to `casters`, as ellipsoids.
void append_casters(const std::vector<AnisotropicGaussian>& particles, std::vector<ShadowCaster>& casters);

// How far the caster reaches from its centre in any direction: a Gaussian's cube half-diagonal
// (kGaussianCubeReach s), a sphere's radius, an ellipsoid's longest semi-axis.
double caster_reach(const ShadowCaster& caster);

// Where the ray o + t w (|w| = 1) can meet the caster: [a, b]; false if nowhere.
bool caster_span(const ShadowCaster& caster, const glm::dvec3& o, const glm::dvec3& w, double& a,
                 double& b);

// The caster's optical depth along one ray with what does not depend on the interval worked out
// once: over [a, b] inside the span it is cumulative(b) - cumulative(a).
struct CasterRayProfile {
  CasterShape shape = CasterShape::gaussian;
  GaussianRayProfile gaussian;
  AnisotropicRaySegment ellipsoid;
  double ellipsoid_entry_erf = 0.0;  // erf(rate (t_enter - t_closest)), the same for every t
  double enter = 0.0, leave = 0.0, extinction = 0.0;  // sphere
  double cumulative(double t) const;
};
CasterRayProfile caster_ray_profile(const ShadowCaster& caster, const glm::dvec3& o, const glm::dvec3& w);

// The caster's optical depth along o + t w (|w| = 1) over t in [a, b].
double caster_optical_depth(const ShadowCaster& caster, const glm::dvec3& o, const glm::dvec3& w,
                            double a, double b);

}  // namespace pyro
