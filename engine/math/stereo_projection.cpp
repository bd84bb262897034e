#include "engine/math/stereo_projection.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace pyro {

EyeMatrices make_eye_matrices(const CameraFrame& mono, const StereoParameters& stereo, Eye eye) {
  // Orthonormal axes in double, as glm::lookAt builds them from the view direction and up.
  const glm::dvec3 f = glm::normalize(glm::dvec3(mono.forward));
  const glm::dvec3 s = glm::normalize(glm::cross(f, glm::dvec3(mono.up)));
  const glm::dvec3 u = glm::cross(s, f);
  const double sign = eye == Eye::left ? -1.0 : 1.0;
  const double half_i = 0.5 * static_cast<double>(stereo.interocular);
  EyeMatrices m;
  m.eye = glm::dvec3(mono.eye) + sign * half_i * s;
  // The view matrix written out from the axes (what glm::lookAt(eye, eye + f, u) computes), so
  // that the rotation rows are bit-identical for both eyes: parallel axes, no vertical parallax.
  m.view = glm::dmat4(1.0);
  for (int i = 0; i < 3; ++i) {
    m.view[i][0] = s[i];
    m.view[i][1] = u[i];
    m.view[i][2] = -f[i];
  }
  m.view[3][0] = -glm::dot(s, m.eye);
  m.view[3][1] = -glm::dot(u, m.eye);
  m.view[3][2] = glm::dot(f, m.eye);
  // Window on the near plane, shifted so the eye's frustum passes through the shared window on
  // the zero-parallax plane: the shift is the eye offset scaled by near / Z0, opposite in sign.
  const double near = mono.near, far = mono.far;
  const double top = near * std::tan(static_cast<double>(mono.fov_y_rad) / 2.0);
  const double half_w = top * static_cast<double>(mono.width) / static_cast<double>(mono.height);
  const double shift = -sign * half_i * near / static_cast<double>(stereo.zero_parallax_distance);
  m.projection = glm::frustum(-half_w + shift, half_w + shift, -top, top, near, far);
  m.view_projection = m.projection * m.view;
  return m;
}

CameraFrame make_eye_frame(const CameraFrame& mono, const StereoParameters& stereo, Eye eye) {
  const EyeMatrices m = make_eye_matrices(mono, stereo, eye);
  CameraFrame f = mono;
  f.eye = glm::vec3(m.eye);
  f.view = glm::mat4(m.view);
  f.projection = glm::mat4(m.projection);
  f.view_projection = glm::mat4(m.view_projection);
  return f;
}

double horizontal_parallax_pixels(const CameraFrame& mono, const StereoParameters& stereo, double z) {
  const double z0 = stereo.zero_parallax_distance;
  const double tan_half_x = std::tan(mono.fov_y_rad / 2.0) * mono.width / mono.height;
  const double window_half_width = z0 * tan_half_x;  // half width of the shared window at Z0
  return stereo.interocular * (1.0 - z0 / z) * (mono.width / 2.0) / window_half_width;
}

}  // namespace pyro
