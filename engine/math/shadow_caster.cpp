#include "engine/math/shadow_caster.h"

#include <algorithm>

namespace pyro {

double caster_reach(const ShadowCaster& caster) {
  return caster.shape == CasterShape::sphere ? caster.size : kGaussianCubeReach * caster.size;
}

bool caster_span(const ShadowCaster& caster, const glm::dvec3& o, const glm::dvec3& w, double& a,
                 double& b) {
  if (caster.shape == CasterShape::gaussian) return gaussian_cube_span(caster.gaussian(), o, w, a, b);
  double extinction;
  return sphere_chord(caster.sphere(), o, w, a, b, extinction);
}

double CasterRayProfile::cumulative(double t) const {
  if (shape == CasterShape::gaussian) return gaussian.cumulative(t);
  return extinction * (std::clamp(t, enter, leave) - enter);
}

CasterRayProfile caster_ray_profile(const ShadowCaster& caster, const glm::dvec3& o, const glm::dvec3& w) {
  CasterRayProfile p;
  p.shape = caster.shape;
  if (caster.shape == CasterShape::gaussian) {
    p.gaussian = gaussian_ray_profile(caster.gaussian(), o, w);
  } else if (!sphere_chord(caster.sphere(), o, w, p.enter, p.leave, p.extinction)) {
    p.enter = p.leave = p.extinction = 0.0;
  }
  return p;
}

double caster_optical_depth(const ShadowCaster& caster, const glm::dvec3& o, const glm::dvec3& w,
                            double a, double b) {
  if (caster.shape == CasterShape::gaussian) return gaussian_optical_depth(caster.gaussian(), o, w, a, b);
  return sphere_optical_depth(caster.sphere(), o, w, a, b);
}

}  // namespace pyro
