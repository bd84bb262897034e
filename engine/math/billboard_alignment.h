#pragma once
// Billboard alignment error (Johnson & McAllister 2005, section 3): how far the image of a
// billboard that faces the viewplane (what the renderer draws: every billboard shares the
// camera's right and up axes) lies from the image of the billboard that faces the viewpoint
// (the exact splat of a rotationally symmetric kernel), measured at one point: E, the midpoint
// of the billboard's right edge.
//
// Coordinates are the paper's camera coordinates (section 3.1): the viewpoint (centre of
// projection) V at the origin, looking down -z, right-handed, y up, the viewplane z = -N.
// Everything here is double precision.
//
// The paper's closed forms for the errors, eqs 11 and 12, do not describe the geometry they
// claim to (docs/billboard_alignment.md has the derivation):
//  - the normalised right axis u* printed under eq 9 has the wrong sign on its z component:
//    (0,1,0) x (V - C) = (-C_z, 0, C_x), the paper prints (-C_z, 0, -C_x), which is not
//    orthogonal to V - C: it turns the billboard by the right angle the wrong way round.
//    Eqs 10 and 11 are correct algebra from that u*, so eq 11 is the error of the mis-turned
//    billboard: wrong sign and wrong size wherever C_x != 0;
//  - eq 12 carries the same sign slip and, in addition, a spurious factor sqrt(C_z^2 + C_x^2) in
//    its numerator, which makes it a length squared instead of a length.
// The functions below compute the errors from the geometry (project the actual points), give
// the printed forms as printed (for comparison only) and the corrected closed forms.
#include <limits>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace pyro {

// Right and up axes of a billboard; the billboard's corners are centre +/- radius*right
// +/- radius*up.
template <typename T>
struct BillboardAxes {
  glm::vec<3, T> right;
  glm::vec<3, T> up;
};

// The axes of a billboard at `centre` that faces the viewpoint `eye` (section 3.1, the
// construction under eq 9; the one source of truth for the renderer, whose GLSL must do exactly
// this):
//   n     = normalize(eye - centre)                 the billboard's normal, towards the eye
//   right = normalize(reference_up x (eye - centre))  u* of the paper, with (0,1,0) = reference_up
//   up    = n x right
// so that right x up = n (the quad's front face looks at the eye), right is horizontal (normal
// to reference_up) and up is reference_up tilted towards the eye. reference_up is the camera's
// up axis (in camera coordinates (0,1,0)). When eye - centre is parallel to reference_up (a
// particle straight above or below the eye), right is undefined; `fallback_right` (the camera's
// right axis) is used instead, projected to be normal to n. A particle on the view axis gets the
// camera's own axes: facing the viewpoint and facing the viewplane then coincide. A particle
// exactly at the eye has no direction to face: it keeps the viewplane axes (fallback_right,
// reference_up), as the shader does (content/shaders/billboard.vert), instead of normalising a
// zero vector into NaN. Requires unit, orthogonal reference_up and fallback_right.
template <typename T>
BillboardAxes<T> viewpoint_facing_axes(const glm::vec<3, T>& centre, const glm::vec<3, T>& eye,
                                       const glm::vec<3, T>& reference_up,
                                       const glm::vec<3, T>& fallback_right) {
  const glm::vec<3, T> to_eye = eye - centre;
  if (!(glm::length(to_eye) > T(0))) return {fallback_right, reference_up};
  const glm::vec<3, T> n = glm::normalize(to_eye);
  glm::vec<3, T> right = glm::cross(reference_up, to_eye);
  // Degenerate when the cross product is lost in rounding next to |to_eye|.
  const T degenerate = T(64) * std::numeric_limits<T>::epsilon() * glm::length(to_eye);
  if (glm::length(right) <= degenerate) right = fallback_right - glm::dot(fallback_right, n) * n;
  right = glm::normalize(right);
  return {right, glm::cross(n, right)};
}

// Perspective projection onto the viewplane z = -N (eq 8): P* = (N P_x / -P_z, N P_y / -P_z).
// Requires P_z < 0 (in front of the viewpoint).
glm::dvec2 project_to_viewplane(const glm::dvec3& p, double near);

// E for a billboard facing the viewplane (eq 9): E_perp = C + (r, 0, 0).
glm::dvec3 viewplane_facing_edge(const glm::dvec3& centre, double radius);

// E for a billboard facing the viewpoint `viewpoint` (eq 10): E_bullet = C + r u*, with
// u* = normalize((0,1,0) x (V - C)) = (-(C_z - V_z), 0, C_x - V_x) / |(C_x - V_x, C_z - V_z)|
// (viewpoint_facing_axes with reference up (0,1,0)). The paper's V is the origin; a stereo eye
// is V = (+/- I/2, 0, 0).
glm::dvec3 viewpoint_facing_edge(const glm::dvec3& centre, double radius,
                                 const glm::dvec3& viewpoint = glm::dvec3(0.0));

// Projection error at E (section 3.1): viewplane-facing minus viewpoint-facing, on the
// viewplane, in the units of the camera coordinates (multiply by pixels per unit at distance N
// for pixels). e_x is eq 11's quantity, e_y eq 12's.
struct ProjectionError {
  double e_x = 0.0;
  double e_y = 0.0;
};

// From the geometry: E_perp* - E_bullet*, both points built and projected by eq 8.
ProjectionError projection_error(const glm::dvec3& centre, double radius, double near);

// Eq 11 exactly as printed:
//   e_x = N r [C_x^2 - C_z s + r C_x - C_z^2] / (-C_z [-C_z s + r C_x]),  s = sqrt(C_z^2 + C_x^2)
double paper_eq11_e_x(const glm::dvec3& centre, double radius, double near);
// Eq 12 exactly as printed:
//   e_y = N r C_x C_y s / (C_z [C_z s - r C_x])
double paper_eq12_e_y(const glm::dvec3& centre, double radius, double near);
// Both, as printed.
ProjectionError projection_error_paper(const glm::dvec3& centre, double radius, double near);

// The corrected closed forms (the algebra of eq 9 minus eq 10 with u* = (-C_z, 0, C_x) / s):
//   e_x = N r [C_x^2 + C_z s + r C_x + C_z^2] / (-C_z [C_z s + r C_x])
//   e_y = N r C_x C_y / (C_z [-C_z s - r C_x])
// Same shape as the printed forms: in eq 11 the signs of the C_z s and C_z^2 terms in the
// numerator and of C_z s in the denominator change; in eq 12 the factor s leaves the numerator
// and the bracket becomes [-C_z s - r C_x].
ProjectionError projection_error_closed_form(const glm::dvec3& centre, double radius, double near);

// Projection error seen from an eye at (eye_x, 0, 0) with the camera axes (a stereo eye with
// parallel axes, Rose 2007 section 1.3; make_eye_frame): the viewpoint-facing billboard is
// turned towards that eye, both E points are projected by that eye's off-axis projection onto
// the shared window on the zero-parallax plane, scaled to the viewplane distance N:
//   x* = N (P_x - eye_x) / -P_z + N eye_x / Z0,   y* = N P_y / -P_z.
// The window shift N eye_x / Z0 is common to both points and cancels in the error; it is there
// so that the points' parallax (right minus left) is the one the viewer sees.
ProjectionError projection_error_from_eye(const glm::dvec3& centre, double radius, double near,
                                          double eye_x, double zero_parallax_distance);

// A point's position on the shared stereo window seen from the eye at (eye_x, 0, 0), in
// viewplane units (the projection used by projection_error_from_eye).
glm::dvec2 project_from_eye(const glm::dvec3& p, double near, double eye_x,
                            double zero_parallax_distance);

// Parallax error (section 3.3) for interocular distance I, defined as
//   (projection error seen from the right eye at (+I/2, 0, 0))
//     - (projection error seen from the left eye at (-I/2, 0, 0)),
// each eye's viewpoint-facing billboard turned towards that eye. Equivalently (tested): the
// parallax (right minus left) of E on the viewplane-facing billboard minus the parallax of E on
// the viewpoint-facing billboards; and the paper's construction, the error surface translated by
// +I/2 minus the surface translated by -I/2: e(C - (I/2,0,0)) - e(C + (I/2,0,0)), because the
// error depends only on the billboard's position relative to the eye (both eyes share the
// camera axes, so E_perp = C + (r,0,0) for both).
struct ParallaxError {
  double horizontal = 0.0;
  double vertical = 0.0;
};
ParallaxError parallax_error(const glm::dvec3& centre, double radius, double near,
                             double interocular);
// The paper's construction from translated surfaces, with any error function e(C).
template <typename ErrorFunction>
ParallaxError parallax_error_from_translated_surfaces(const glm::dvec3& centre, double interocular,
                                                      ErrorFunction e) {
  const glm::dvec3 half(0.5 * interocular, 0.0, 0.0);
  const ProjectionError right_eye = e(centre - half);  // surface translated by +I/2
  const ProjectionError left_eye = e(centre + half);   // surface translated by -I/2
  return {right_eye.e_x - left_eye.e_x, right_eye.e_y - left_eye.e_y};
}

// The domain of the analysis: the centre, E_perp and the viewpoint-facing E of the mono eye and
// of both stereo eyes (at +/- I/2) all strictly beyond the viewplane (z < -N), with N > 0,
// r >= 0, I >= 0. Returns an empty string inside it, else what is wrong, in words.
std::string billboard_alignment_domain_problem(const glm::dvec3& centre, double radius, double near,
                                               double interocular);

}  // namespace pyro
