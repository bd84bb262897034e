#include "engine/math/camera_math.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace pyro {

CameraFrame make_camera_frame(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up,
                              float fov_y_deg, float near, float far, int width, int height) {
  CameraFrame f;
  f.eye = eye;
  f.forward = glm::normalize(target - eye);
  f.right = glm::normalize(glm::cross(f.forward, up));
  f.up = glm::cross(f.right, f.forward);
  f.view = glm::lookAt(eye, target, up);
  f.fov_y_rad = glm::radians(fov_y_deg);
  f.projection = glm::perspective(f.fov_y_rad, static_cast<float>(width) / height, near, far);
  f.view_projection = f.projection * f.view;
  f.near = near;
  f.far = far;
  f.width = width;
  f.height = height;
  return f;
}

namespace {

// Clip space to pixels: x right, y down, the viewport covering [0, width] x [0, height].
template <typename T>
glm::vec<2, T> clip_to_pixels(const glm::mat<4, 4, T>& view_projection, int width, int height,
                              const glm::vec<3, T>& p) {
  const glm::vec<4, T> clip = view_projection * glm::vec<4, T>(p, T(1));
  const T nx = clip.x / clip.w, ny = clip.y / clip.w;
  return {(nx * T(0.5) + T(0.5)) * static_cast<T>(width),
          (T(0.5) - ny * T(0.5)) * static_cast<T>(height)};
}

}  // namespace

glm::vec2 project_to_pixels(const CameraFrame& f, const glm::vec3& p) {
  return clip_to_pixels(f.view_projection, f.width, f.height, p);
}

glm::dvec2 project_to_pixels(const glm::dmat4& view_projection, int width, int height,
                             const glm::dvec3& p) {
  return clip_to_pixels(view_projection, width, height, p);
}

}  // namespace pyro
