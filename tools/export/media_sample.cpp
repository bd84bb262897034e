#include "tools/export/media_sample.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "engine/math/sphere_field.h"

namespace pyro {

double extinction_at(const MediaSample& s, const glm::dvec3& p) {
  const ShadowCaster& f = s.field;
  const glm::dvec3 d = p - f.c;
  switch (f.shape) {
    case CasterShape::gaussian: {
      const double e = 3.0 * f.size;
      if (std::abs(d.x) > e || std::abs(d.y) > e || std::abs(d.z) > e) return 0.0;
      return f.k * std::exp(-glm::dot(d, d) / (2.0 * f.size * f.size));
    }
    case CasterShape::ellipsoid: {
      const glm::dvec3 u = glm::dmat3(f.whitening) * d;
      const double m2 = glm::dot(u, u);
      return m2 <= double(kAnisotropicExtent * kAnisotropicExtent) ? f.k * std::exp(-0.5 * m2) : 0.0;
    }
    case CasterShape::sphere:
      // Off the centre by a millionth of the radius: the profile is infinite (but integrable) there.
      return f.k * sphere_field_profile_tabulated(std::max(glm::length(d) / f.size, 1e-6));
  }
  return 0.0;
}

double sample_reach(const MediaSample& s) {
  // A Gaussian's cube reaches 3 s along each axis; a sphere its radius; an ellipsoid its reach.
  return s.field.shape == CasterShape::gaussian ? 3.0 * s.field.size : caster_reach(s.field);
}

}  // namespace pyro
