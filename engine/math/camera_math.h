#pragma once
// Camera frames and projections (right-handed, camera looks down -z, GL clip depth [-1, 1]).
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace pyro {

struct CameraFrame {
  glm::vec3 eye{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit view direction
  glm::vec3 right{1.0f, 0.0f, 0.0f};     // unit, camera x axis
  glm::vec3 up{0.0f, 1.0f, 0.0f};        // unit, camera y axis
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::mat4 view_projection{1.0f};
  float near = 0.1f, far = 100.0f;
  float fov_y_rad = 0.785398f;
  int width = 1, height = 1;
};

// Frame for an eye at `eye` looking at `target`. `up` must not be parallel to the view direction.
CameraFrame make_camera_frame(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up,
                              float fov_y_deg, float near, float far, int width, int height);

// Distance of p in front of the eye along the view axis (view-space -z).
inline float view_depth(const CameraFrame& f, const glm::vec3& p) {
  return (p.x - f.eye.x) * f.forward.x + (p.y - f.eye.y) * f.forward.y +
         (p.z - f.eye.z) * f.forward.z;
}

// View depth of a window depth d in [0, 1] under a perspective projection with these clip
// distances (glm::perspective, OpenGL's default depth range): z_ndc = 2 d - 1,
// z = 2 n f / (f + n - z_ndc (f - n)); d = 0 is the near plane, d = 1 the far one.
inline float window_to_view_depth(float d, float near, float far) {
  const float z_ndc = 2.0f * d - 1.0f;
  return 2.0f * near * far / (far + near - z_ndc * (far - near));
}

// 1/z for a window depth d is affine in d: 1/z = x - y d with (x, y) = (1/n, (f - n) / (n f)),
// the same convention as window_to_view_depth (content/shaders/inverse_depth.glsl's
// u_inverse_depth).
inline glm::vec2 inverse_depth_terms(float near, float far) {
  return {1.0f / near, (far - near) / (near * far)};
}

// Pixel coordinates (x right, y down, pixel centres at +0.5) of world point p.
glm::vec2 project_to_pixels(const CameraFrame& f, const glm::vec3& p);
// The same mapping in double precision through a double view-projection matrix (for analyses,
// e.g. with make_eye_matrices in stereo_projection.h).
glm::dvec2 project_to_pixels(const glm::dmat4& view_projection, int width, int height,
                             const glm::dvec3& p);

}  // namespace pyro
