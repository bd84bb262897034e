#pragma once
// Stereo pairs from two off-axis projections with parallel view axes (Rose 2007, section 1.3;
// Johnson & McAllister 2005, section 3.3): each eye is the mono eye moved by -/+ I/2 along the
// camera's right axis, looking along the same direction, with a frustum sheared so that both
// frusta share one window on the zero-parallax plane. Never toe-in: toe-in rotates the eyes
// and introduces vertical parallax; parallel axes keep it exactly zero.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "engine/math/camera_math.h"

namespace pyro {

enum class Eye { left, right };

struct StereoParameters {
  float interocular = 0.065f;        // I, world units between the eyes; >= 0
  float zero_parallax_distance = 5.0f;  // Z0, view depth where left and right images coincide; > 0
};

// One eye's position and matrices in double precision: the construction itself. The mono axes
// are first made exactly orthonormal in double (f = normalize(forward),
// s = normalize(f x up), u = s x f); the eye is mono.eye -/+ (I/2) s; both eyes' view matrices
// share the rows s, u, -f (parallel axes) and differ only in translation; the projection is
// glm::frustum with the window shifted by -/+ (I/2) near / Z0. make_eye_frame rounds this to
// float for the renderer; analyses that resolve parallax far below a pixel (pyro analyze
// stereo) project through these matrices.
struct EyeMatrices {
  glm::dvec3 eye{0.0};
  glm::dmat4 view{1.0};
  glm::dmat4 projection{1.0};
  glm::dmat4 view_projection{1.0};
};
EyeMatrices make_eye_matrices(const CameraFrame& mono, const StereoParameters& stereo, Eye eye);

// The frame of one eye: `mono` moved along its right axis by -I/2 (left) or +I/2 (right), with
// the off-axis projection: make_eye_matrices rounded to float. Axes, near, far, fov and size
// are those of `mono`.
CameraFrame make_eye_frame(const CameraFrame& mono, const StereoParameters& stereo, Eye eye);

// Closed form of the horizontal screen parallax of a point at view depth z, in pixels
// (positive: behind the zero-parallax plane, uncrossed):
//   p = I * (1 - Z0 / z) * (width / 2) / (Z0 * tan(fov_x / 2))
// i.e. the parallax on the zero-parallax window, I (z - Z0) / z, scaled to pixels.
double horizontal_parallax_pixels(const CameraFrame& mono, const StereoParameters& stereo, double z);

}  // namespace pyro
