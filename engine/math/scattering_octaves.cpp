#include "engine/math/scattering_octaves.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/math/phase_function.h"

namespace pyro {

double sun_scattering(const SunScattering& s, double mu, double tau) {
  const ScatteringOctaves& o = s.octaves;
  if (o.octaves == 1 && s.anisotropy == 0.0) return std::exp(-tau);
  double sum = 0.0, a = 1.0, b = 1.0, c = 1.0;
  for (int i = 0; i < o.octaves; ++i) {
    sum += b * 4.0 * std::numbers::pi * henyey_greenstein(mu, c * s.anisotropy) * std::exp(-a * tau);
    a *= o.attenuation;
    b *= o.contribution;
    c *= o.eccentricity;
  }
  return sum;
}

void validate(const SunScattering& s) {
  const ScatteringOctaves& o = s.octaves;
  if (!(s.anisotropy > -1.0 && s.anisotropy < 1.0))
    throw std::invalid_argument("anisotropy must lie in (-1, 1)");
  if (o.octaves < 1 || o.octaves > 16) throw std::invalid_argument("octaves must be 1 to 16");
  if (!(o.attenuation > 0.0 && o.attenuation <= 1.0))
    throw std::invalid_argument("attenuation must lie in (0, 1]");
  if (!(o.contribution >= 0.0 && o.contribution <= 1.0))
    throw std::invalid_argument("contribution must lie in [0, 1]");
  if (!(o.eccentricity >= 0.0 && o.eccentricity <= 1.0))
    throw std::invalid_argument("eccentricity must lie in [0, 1]");
}

}  // namespace pyro
