#pragma once
// erf from a table, for the loops that call it millions of times a frame (the opacity shadow
// map's columns): linear interpolation between 8192 nodes on [-4, 4], and +-1 beyond, where
// |1 - erf(4)| < 1.6e-8. Interpolation error <= h^2/8 max|erf''| = h^2/8 * 2 sqrt(2/(pi e))
// ~ 1.1e-7 at h = 8/8192 (tested against std::erf): below a float's resolution of the depths it
// feeds.
namespace pyro {

double tabulated_erf(double x);

}  // namespace pyro
