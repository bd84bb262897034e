#pragma once
// The suns the lighting benchmarks light a volume from: direction k of n has azimuth 360 k / n
// degrees and stands 40 degrees above the horizon. The vector is the direction the light
// travels (down and across), unit length.
#include <cmath>
#include <numbers>

#include <glm/vec3.hpp>

namespace pyro {

inline glm::dvec3 sun_direction(int k, int n) {
  const double azimuth = 2.0 * std::numbers::pi * k / n, elevation = 40.0 * std::numbers::pi / 180.0;
  return -glm::dvec3(std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                     std::cos(elevation) * std::sin(azimuth));
}

}  // namespace pyro
