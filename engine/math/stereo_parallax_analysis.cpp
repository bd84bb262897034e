#include "engine/math/stereo_parallax_analysis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/vec4.hpp>

namespace pyro {

namespace {

// View depth (distance along the view axis) of p in an eye frame.
double view_depth(const EyeMatrices& eye, const glm::dvec3& p) {
  return -(eye.view * glm::dvec4(p, 1.0)).z;
}

}  // namespace

StereoParallaxReport analyze_stereo_parallax(const CameraFrame& mono,
                                             const StereoParameters& stereo, int samples_per_axis) {
  if (samples_per_axis < 2)
    throw std::invalid_argument("analyze_stereo_parallax: samples_per_axis must be >= 2");
  const int n = samples_per_axis;
  const EyeMatrices left = make_eye_matrices(mono, stereo, Eye::left);
  const EyeMatrices right = make_eye_matrices(mono, stereo, Eye::right);
  const CameraFrame left_f = make_eye_frame(mono, stereo, Eye::left);
  const CameraFrame right_f = make_eye_frame(mono, stereo, Eye::right);

  const double tan_y = std::tan(static_cast<double>(mono.fov_y_rad) / 2.0);
  const double tan_x = tan_y * mono.width / mono.height;
  const glm::dvec3 eye(mono.eye), forward(mono.forward), right_axis(mono.right), up(mono.up);
  const double log_near = std::log(static_cast<double>(mono.near));
  const double log_far = std::log(static_cast<double>(mono.far));

  StereoParallaxReport r;
  r.min_horizontal_parallax = std::numeric_limits<double>::infinity();
  r.max_horizontal_parallax = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k) {
    // The end points exactly on the near and far planes.
    const double d = k == 0       ? static_cast<double>(mono.near)
                     : k == n - 1 ? static_cast<double>(mono.far)
                                  : std::exp(log_near + (log_far - log_near) * k / (n - 1));
    for (int j = 0; j < n; ++j) {
      const double v = -1.0 + 2.0 * j / (n - 1);
      for (int i = 0; i < n; ++i) {
        const double h = -1.0 + 2.0 * i / (n - 1);
        const glm::dvec3 p =
            eye + d * forward + (h * d * tan_x) * right_axis + (v * d * tan_y) * up;
        // The closed form at the point's view depth as the eye frames see it (both eyes share
        // it: they are offset along s, normal to f), not at d: mono.forward is a float vector,
        // and its direction differs from the double f of the eye frames by ~1e-8.
        const double closed_form = horizontal_parallax_pixels(mono, stereo, view_depth(left, p));
        const glm::dvec2 pl = project_to_pixels(left.view_projection, mono.width, mono.height, p);
        const glm::dvec2 pr = project_to_pixels(right.view_projection, mono.width, mono.height, p);
        const double parallax = pr.x - pl.x;
        r.max_vertical_parallax = std::max(r.max_vertical_parallax, std::abs(pr.y - pl.y));
        r.max_horizontal_parallax_error =
            std::max(r.max_horizontal_parallax_error, std::abs(parallax - closed_form));
        r.min_horizontal_parallax = std::min(r.min_horizontal_parallax, parallax);
        r.max_horizontal_parallax = std::max(r.max_horizontal_parallax, parallax);

        const glm::vec3 pf(p);
        const double closed_form_f =
            horizontal_parallax_pixels(mono, stereo, view_depth(left, glm::dvec3(pf)));
        const glm::vec2 fl = project_to_pixels(left_f, pf);
        const glm::vec2 fr = project_to_pixels(right_f, pf);
        r.max_vertical_parallax_float =
            std::max(r.max_vertical_parallax_float, std::abs(static_cast<double>(fr.y - fl.y)));
        r.max_horizontal_parallax_error_float = std::max(
            r.max_horizontal_parallax_error_float,
            std::abs(static_cast<double>(fr.x) - static_cast<double>(fl.x) - closed_form_f));
      }
    }
  }
  r.points = static_cast<long long>(n) * n * n;
  return r;
}

}  // namespace pyro
