#pragma once
// The ray through a pixel centre of the GL camera (engine/math/camera_math.h): pixel (x, y),
// y down, centre at +0.5, the same perspective glm::perspective builds from fov_y and the
// aspect width / height. The direction is unit length.
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "engine/math/camera_math.h"

namespace pyro {

inline glm::dvec3 pixel_ray_direction(const CameraFrame& f, double x, double y) {
  const double t = std::tan(0.5 * double(f.fov_y_rad));
  const double aspect = double(f.width) / double(f.height);
  const double nx = (2.0 * x / f.width - 1.0) * t * aspect;
  const double ny = (1.0 - 2.0 * y / f.height) * t;
  return glm::normalize(glm::dvec3(f.forward) + nx * glm::dvec3(f.right) + ny * glm::dvec3(f.up));
}

}  // namespace pyro
