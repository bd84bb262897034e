#include "engine/math/shadow_caster.h"

#include <algorithm>
#include <cmath>

namespace pyro {

ShadowCaster::ShadowCaster(const AnisotropicGaussian& g)
    : shape(CasterShape::ellipsoid),
      c(g.centre),
      size(double(kAnisotropicExtent) * std::max({g.scale.x, g.scale.y, g.scale.z})),
      k(g.extinction),
      whitening(whitening_matrix(g)) {}

AnisotropicRaySegment ShadowCaster::ellipsoid(const glm::dvec3& o, const glm::dvec3& w) const {
  const glm::dmat3 m(whitening);
  return anisotropic_ray_segment(m, m * (o - c), k, w);
}

void append_casters(const std::vector<AnisotropicGaussian>& particles, std::vector<ShadowCaster>& casters) {
  for (const AnisotropicGaussian& g : particles)
    if (g.extinction > 0.0f) casters.emplace_back(g);
}

double caster_reach(const ShadowCaster& caster) {
  return caster.shape == CasterShape::gaussian ? kGaussianCubeReach * caster.size : caster.size;
}

bool caster_span(const ShadowCaster& caster, const glm::dvec3& o, const glm::dvec3& w, double& a,
                 double& b) {
  if (caster.shape == CasterShape::gaussian) return gaussian_cube_span(caster.gaussian(), o, w, a, b);
  if (caster.shape == CasterShape::ellipsoid) {
    const AnisotropicRaySegment s = caster.ellipsoid(o, w);
    a = s.t_enter;
    b = s.t_exit;
    return s.hit;
  }
  double extinction;
  return sphere_chord(caster.sphere(), o, w, a, b, extinction);
}

double CasterRayProfile::cumulative(double t) const {
  if (shape == CasterShape::gaussian) return gaussian.cumulative(t);
  if (shape == CasterShape::ellipsoid) {  // ellipsoid.depth(-infinity, t), its entry's erf kept
    if (!ellipsoid.hit || !(t > ellipsoid.t_enter)) return 0.0;
    const double hi = std::min(t, ellipsoid.t_exit);
    return ellipsoid.peak * (std::erf(ellipsoid.rate * (hi - ellipsoid.t_closest)) - ellipsoid_entry_erf);
  }
  return extinction * (std::clamp(t, enter, leave) - enter);
}

CasterRayProfile caster_ray_profile(const ShadowCaster& caster, const glm::dvec3& o, const glm::dvec3& w) {
  CasterRayProfile p;
  p.shape = caster.shape;
  if (caster.shape == CasterShape::gaussian) {
    p.gaussian = gaussian_ray_profile(caster.gaussian(), o, w);
  } else if (caster.shape == CasterShape::ellipsoid) {
    p.ellipsoid = caster.ellipsoid(o, w);
    p.ellipsoid_entry_erf = std::erf(p.ellipsoid.rate * (p.ellipsoid.t_enter - p.ellipsoid.t_closest));
  } else if (!sphere_chord(caster.sphere(), o, w, p.enter, p.leave, p.extinction)) {
    p.enter = p.leave = p.extinction = 0.0;
  }
  return p;
}

double caster_optical_depth(const ShadowCaster& caster, const glm::dvec3& o, const glm::dvec3& w,
                            double a, double b) {
  if (caster.shape == CasterShape::gaussian) return gaussian_optical_depth(caster.gaussian(), o, w, a, b);
  if (caster.shape == CasterShape::ellipsoid) return caster.ellipsoid(o, w).depth(a, b);
  return sphere_optical_depth(caster.sphere(), o, w, a, b);
}

}  // namespace pyro
