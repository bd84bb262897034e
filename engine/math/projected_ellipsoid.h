#pragma once
// The screen rectangle covered by an anisotropic Gaussian particle's ellipsoid m <= 3
// (engine/particles/anisotropic_gaussian.h) under a projective camera, in closed form
// (Sigg, Weyrich, Botsch, Gross 2006, "GPU-based ray-casting of quadratic surfaces": the bounding
// box of a projected quadric).
//
// In the particle's parameter space the ellipsoid is the unit sphere x^T D x = 0 (x homogeneous,
// D = diag(1, 1, 1, -1)); the map to world space is M = [R diag(3 s) | c], and to clip space
// T = P V M. A plane with parameter-space coefficients p touches the sphere when
// <p, p> = p^T D^-1 p = 0 (D^-1 = D), cuts it when <p, p> > 0 and misses it when <p, p> < 0.
// The edge x_ndc = lambda is the clip-space plane x - lambda w = 0, whose parameter-space
// coefficients are r1 - lambda r4 (r_i the rows of T). Tangency gives a quadratic in lambda:
//   <r4, r4> lambda^2 - 2 <r1, r4> lambda + <r1, r1> = 0,
//   lambda = (<r1, r4> -+ sqrt(<r1, r4>^2 - <r1, r1> <r4, r4>)) / <r4, r4>,
// the left and right edges; r2 in place of r1 gives the bottom and top. Both are real and the
// rectangle is the whole image of the ellipsoid while the ellipsoid lies wholly in front of the
// eye plane (w = 0, coefficients r4: <r4, r4> < 0 and r4.w > 0). A particle that meets the near
// plane (z + w = 0, coefficients r3 + r4) or holds the eye is drawn over the whole viewport
// instead, since what it shows there is not bounded by that rectangle.
// The vertex shader content/shaders/anisotropic_splat.vert evaluates the same formula in float.
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "engine/particles/anisotropic_gaussian.h"

namespace pyro {

enum class EllipsoidCover {
  rectangle,    // wholly beyond the near plane: lo..hi bound its image
  full_screen,  // meets the near plane, or lies (partly) between it and the eye, or holds the eye
  hidden        // wholly behind the eye plane: invisible
};

struct ProjectedEllipsoid {
  EllipsoidCover cover = EllipsoidCover::hidden;
  glm::dvec2 lo{0.0}, hi{0.0};  // NDC rectangle (rectangle only)
  double depth_ndc = -1.0;      // NDC z of the centre, or -1 (the near plane) when it is not
                                // beyond the near plane
};

// The particle's ellipsoid m <= kAnisotropicExtent seen through `view_projection`
// (a GL clip-space projection, depth -w..w).
ProjectedEllipsoid project_ellipsoid(const AnisotropicGaussian& g, const glm::dmat4& view_projection);

}  // namespace pyro
