#include "systems/runtime/cloud_import/grid_framing.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "systems/runtime/cloud_import/cloud_import.h"

namespace pyro {

CameraDescription framing_camera(const GridHeader& grid) {
  CameraDescription c;
  c.fov_y_deg = 45.0f;
  if (grid.box_voxels() == 0) return c;
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

std::vector<CameraDescription> views_around(const GridHeader& grid) {
  std::vector<CameraDescription> views = {framing_camera(grid)};
  if (grid.box_voxels() == 0) return views;
  const CameraDescription first = views[0];  // a copy: views grows below
  const glm::vec3 centre = first.target;
  const float distance = glm::length(first.position - centre);
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::vec3& axis : axes) {
    CameraDescription c = first;
    c.position = centre + distance * axis;
    c.up = axis.y != 0.0f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);  // never along the view
    views.push_back(c);
  }
  return views;
}

std::optional<CameraDescription> view_inside(const DenseGrid& grid) {
  if (grid.empty() || std::min({grid.dims[0], grid.dims[1], grid.dims[2]}) < 8) return std::nullopt;
  glm::dvec3 lo, hi;
  grid_world_bounds(grid, lo, hi);
  CameraDescription inside = framing_camera(grid);
  inside.position = inside.target;
  inside.target = inside.position + glm::vec3(1, 0, 0);
  inside.fov_y_deg = 90.0f;
  inside.near = float(1e-4 * glm::length(hi - lo));
  inside.far = float(glm::length(hi - lo));
  return inside;
}

CameraFrame camera_frame(const CameraDescription& c, int width, int height) {
  return make_camera_frame(c.position, c.target, c.up, c.fov_y_deg, c.near, c.far, width, height);
}

VolumeMedium default_medium(const GridHeader& grid) {
  VolumeMedium m;
  m.extinction = default_extinction(grid);
  return m;
}

}  // namespace pyro
