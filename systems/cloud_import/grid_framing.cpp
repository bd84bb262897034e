#include "systems/cloud_import/grid_framing.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "systems/cloud_import/cloud_import.h"

namespace pyro {

CameraDescription framing_camera(const DenseGrid& grid) {
  CameraDescription c;
  c.fov_y_deg = 45.0f;
  if (grid.empty()) return c;
  glm::dvec3 lo, hi;
  grid_world_bounds(grid, lo, hi);
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double radius = 0.5 * glm::length(hi - lo);
  const double distance = radius / std::sin(0.5 * glm::radians(double(c.fov_y_deg)));
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.35, 0.25, 1.0));
  c.target = glm::vec3(centre);
  c.position = glm::vec3(centre + distance * dir);
  c.up = {0.0f, 1.0f, 0.0f};
  c.near = float(std::max(1e-3 * distance, distance - 1.05 * radius));
  c.far = float(distance + 1.05 * radius);
  return c;
}

CameraFrame camera_frame(const CameraDescription& c, int width, int height) {
  return make_camera_frame(c.position, c.target, c.up, c.fov_y_deg, c.near, c.far, width, height);
}

VolumeMedium default_medium(const DenseGrid& grid) {
  VolumeMedium m;
  m.extinction = default_extinction(grid);
  return m;
}

}  // namespace pyro
