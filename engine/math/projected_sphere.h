#pragma once
// The screen rectangle a sphere's image covers under a perspective projection, in closed form.
//
// Derivation (ours): the image's left and right edges are the images of the two planes through
// the eye that contain the camera's y axis and touch the sphere. Such a plane is x = u d (d the
// view depth, -z), and touches the sphere of centre (x, y, -D) and radius r where its distance
// from the centre is r: (x - u D)^2 = r^2 (1 + u^2), a quadratic in u whose roots are
//   u = (x D -+ r sqrt(x^2 + D^2 - r^2)) / (D^2 - r^2),
// real and finite while the sphere lies wholly in front of the eye plane (D > r). The same with y
// gives the bottom and top. A projection of the usual form (clip w = -z) maps u to
// x_ndc = P[0][0] u - P[2][0] (P[2][0] the off-axis term), and y with P[1][1] and P[2][1].
// The shader content/shaders/sphere_billboard.vert evaluates the same formula.
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace pyro {

struct ScreenRect {
  glm::vec2 lo{0.0f}, hi{0.0f};  // window pixels of a viewport from (0, 0)
  glm::vec2 size() const { return hi - lo; }
  glm::vec2 centre() const { return 0.5f * (lo + hi); }
};

// The rectangle of the sphere (centre in view space, the camera looking down -z) in a viewport
// of `viewport` pixels, into `out`. False, and `out` untouched, unless the sphere lies wholly in
// front of the eye plane (-centre.z > radius > 0).
bool projected_sphere_rect(const glm::vec3& centre, float radius, const glm::mat4& projection,
                           glm::vec2 viewport, ScreenRect& out);

}  // namespace pyro
