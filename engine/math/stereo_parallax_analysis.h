#pragma once
// Measures a stereo pair's parallax over the whole view volume: a grid of points from the near
// to the far plane and from edge to edge of the mono frustum is projected through both eye
// frames (stereo_projection.h). With parallel axes and off-axis frusta (Rose 2007, section 1.3;
// Johnson & McAllister 2005, section 3.3) the vertical parallax is zero and the horizontal
// parallax of a point depends on its view depth only, as horizontal_parallax_pixels says.
//
// Two paths: the double path projects through make_eye_matrices (the construction, in double),
// the float path through make_eye_frame and project_to_pixels (what the renderer gets). Float
// rounding alone leaves vertical parallax of the order of 1e-4 pixels in the float path for an
// oblique camera; the double path resolves the construction to about 1e-10 pixels.
#include <glm/mat4x4.hpp>

#include "engine/math/camera_math.h"
#include "engine/math/stereo_projection.h"

namespace pyro {

struct StereoParallaxReport {
  long long points = 0;  // samples_per_axis^3
  // Double path.
  double max_vertical_parallax = 0.0;          // max |y_right - y_left|, pixels
  double max_horizontal_parallax_error = 0.0;  // max |(x_right - x_left) - closed form|, pixels
  double min_horizontal_parallax = 0.0;        // range of x_right - x_left, pixels
  double max_horizontal_parallax = 0.0;
  // Float path (make_eye_frame, project_to_pixels in float).
  double max_vertical_parallax_float = 0.0;
  double max_horizontal_parallax_error_float = 0.0;
};

// Samples view depths d_k from near to far, evenly spaced in log d (parallax varies as 1/d),
// and at each depth an n x n grid from edge to edge of the mono frustum:
//   p = eye + d forward + (-1 + 2i/(n-1)) d tan_x right + (-1 + 2j/(n-1)) d tan_y up.
// samples_per_axis >= 2.
StereoParallaxReport analyze_stereo_parallax(const CameraFrame& mono,
                                             const StereoParameters& stereo, int samples_per_axis);

}  // namespace pyro
