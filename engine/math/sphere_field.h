#pragma once
// The extinction field inside a spherical particle whose projection along every line is the
// explosion model's (engine/math/sphere_line_integral.h: Umenhoffer et al. 2006, eq. 2): a field
// f(p) = k g(|p - c| / r) whose line integral at miss distance d is k (1 - d/r) 2 sqrt(r^2 - d^2),
// the same for every direction, so that a voxel grid of it projects as the billboards draw.
//
// Derivation (ours). A radially symmetric field projects to its Abel transform
//   F(d) = 2 int_d^r f(rho) rho / sqrt(rho^2 - d^2) drho,
// inverted by f(rho) = -(1/pi) int_rho^r F'(d) / sqrt(d^2 - rho^2) dd (Bracewell, "The Fourier
// Transform and its Applications", ch. 14). On the unit sphere (r = 1, k = 1) write
// F(d) = 2 sqrt(1 - d^2) - 2 d sqrt(1 - d^2): the first term is the projection of the constant 1;
// for the second, F_b = d sqrt(1 - d^2) has F_b' = (1 - 2 d^2) / sqrt(1 - d^2), and the two
// integrals int_rho^1 dd / sqrt((1 - d^2)(d^2 - rho^2)) = K(m) and
// int_rho^1 d^2 dd / sqrt((1 - d^2)(d^2 - rho^2)) = E(m), m = sqrt(1 - rho^2) (Gradshteyn &
// Ryzhik 3.152.10 and 3.153.10; K, E the complete elliptic integrals of modulus m) give
// f_b = (2 E(m) - K(m)) / pi. So
//   g(x) = 1 - (2 / pi) (2 E(m) - K(m)),   m = sqrt(1 - x^2),   0 <= x < 1,
// 0 at the rim (E = K = pi/2) and rising to a logarithmic singularity at the centre (K -> inf),
// which is what the cusp of F at d = 0 needs; its integral over any cell is finite.
namespace pyro {

// g(x) above: the field of the unit sphere of unit k at distance x from its centre, 0 for x >= 1.
// x = 0 is infinite; callers sample it off the centre (a cell average).
double sphere_field_profile(double x);

// The same from a table, for voxelizing: near the centre K(m) = ln(4 / x) + O(x^2 ln x)
// (Abramowitz & Stegun 17.3.26) and E(m) -> 1, so g(x) + (2 / pi) ln x is continuous on [0, 1]
// (1 + (2 / pi)(ln 4 - 2) at 0, 0 at the rim); that remainder is tabulated at 4097 points and
// interpolated linearly, and the logarithm added back. Within 2e-4 of sphere_field_profile
// (tested), at a fraction of its cost (two elliptic integrals a call).
double sphere_field_profile_tabulated(double x);

}  // namespace pyro
