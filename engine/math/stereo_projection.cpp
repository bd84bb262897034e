#include "engine/math/stereo_projection.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace pyro {

CameraFrame make_eye_frame(const CameraFrame& mono, const StereoParameters& stereo, Eye eye) {
  CameraFrame f = mono;
  const float sign = eye == Eye::left ? -1.0f : 1.0f;
  const float half_i = 0.5f * stereo.interocular;
  f.eye = mono.eye + sign * half_i * mono.right;
  f.view = glm::lookAt(f.eye, f.eye + mono.forward, mono.up);
  // Window on the near plane, shifted so the eye's frustum passes through the shared window on
  // the zero-parallax plane: the shift is the eye offset scaled by near / Z0, opposite in sign.
  const float top = mono.near * std::tan(mono.fov_y_rad / 2.0f);
  const float half_w = top * static_cast<float>(mono.width) / static_cast<float>(mono.height);
  const float shift = -sign * half_i * mono.near / stereo.zero_parallax_distance;
  f.projection = glm::frustum(-half_w + shift, half_w + shift, -top, top, mono.near, mono.far);
  f.view_projection = f.projection * f.view;
  return f;
}

double horizontal_parallax_pixels(const CameraFrame& mono, const StereoParameters& stereo, double z) {
  const double z0 = stereo.zero_parallax_distance;
  const double tan_half_x = std::tan(mono.fov_y_rad / 2.0) * mono.width / mono.height;
  const double window_half_width = z0 * tan_half_x;  // half width of the shared window at Z0
  return stereo.interocular * (1.0 - z0 / z) * (mono.width / 2.0) / window_half_width;
}

}  // namespace pyro
