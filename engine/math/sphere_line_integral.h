#pragma once
// The optical depth of one spherical particle along a straight line, in closed form: what the
// light phase integrates along shadow rays through explosion media.
//
// Umenhoffer et al. 2006 (eq. 2) give a spherical particle of radius r the opacity
// 1 - exp(-tau (1 - d/r) ds) along a ray at distance d from its centre that runs ds inside it:
// the extinction is k (1 - d/r), constant along the ray and falling to 0 at the rim. The same
// model serves any ray, so along o + t w (|w| = 1), with tc = (c - o).w the closest approach and
// d^2 = |c - o|^2 - tc^2, the particle occupies [tc - h, tc + h], h = sqrt(r^2 - d^2), and its
// optical depth over [a, b] is k (1 - d/r) |[a, b] n [tc - h, tc + h]|.
#include <glm/vec3.hpp>

namespace pyro {

struct ConeSphere {
  glm::dvec3 c{0.0};
  double r = 1.0;  // radius
  double k = 0.0;  // extinction along a ray through the centre (tau, 1 / length)
};

// Where the ray o + t w (|w| = 1) is inside the sphere: [a, b] and the extinction along it,
// k (1 - d / r); false if the ray misses.
bool sphere_chord(const ConeSphere& s, const glm::dvec3& o, const glm::dvec3& w, double& a,
                  double& b, double& extinction);

// The optical depth of the sphere along o + t w (|w| = 1) over t in [a, b].
double sphere_optical_depth(const ConeSphere& s, const glm::dvec3& o, const glm::dvec3& w,
                            double a, double b);

// The sphere's opacity integrated over the disc it projects to,
//   A = int_0^r (1 - exp(-k (1 - d/r) 2 sqrt(r^2 - d^2))) 2 pi d dd
// (Gauss-Legendre in d): seen from far away, an emitting sphere of radiance L is a point source
// of intensity L A. From pi r^2 (opaque) down to 4 pi k r^3 (1/3 - pi/16) as k -> 0.
double sphere_opacity_area(double r, double k);

}  // namespace pyro
