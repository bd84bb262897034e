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

glm::vec2 project_to_pixels(const CameraFrame& f, const glm::vec3& p) {
  const glm::vec4 clip = f.view_projection * glm::vec4(p, 1.0f);
  const float nx = clip.x / clip.w, ny = clip.y / clip.w;
  return {(nx * 0.5f + 0.5f) * f.width, (0.5f - ny * 0.5f) * f.height};
}

}  // namespace pyro
