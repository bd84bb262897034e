#pragma once
// The splatting footprint of the Gaussian reconstruction kernel (Johnson & McAllister 2005,
// sections 1.3 and 2.1). The kernel is h(x,y,z) = exp(-(x^2+y^2+z^2)/2) (eq. 3), clamped to
// [-extent, extent] on every axis (the paper uses extent 3). The footprint at (x, y) is the
// integral of h along z (eq. 1); the table holds it at size x size evenly spaced nodes over
// [-extent, extent]^2 (eq. 4), computed by composite quadrature and then scaled by its largest
// entry so that it lies in [0, 1] (section 2.1).
//
// A property worth knowing: h is separable, so every entry is exp(-(x^2+y^2)/2) times the same
// 1D quadrature of exp(-z^2/2). Scaling by the largest entry therefore cancels the quadrature
// error exactly; it shows only in the raw integrals (`raw`), which is what the accuracy figures
// against the closed form (erf) measure. What the renderer sees is the scaled table sampled with
// bilinear filtering; its error is dominated by the node spacing, not by the quadrature.
#include <string>
#include <vector>

namespace pyro {

enum class QuadratureRule { trapezoid, simpson, midpoint };

const char* quadrature_rule_name(QuadratureRule rule);
// Returns false when `name` is not a rule name.
bool parse_quadrature_rule(const std::string& name, QuadratureRule& rule);

struct FootprintTable {
  int size = 0;
  int intervals = 0;
  double extent = 3.0;
  QuadratureRule rule = QuadratureRule::trapezoid;
  std::vector<double> raw;     // size*size integrals, row-major, row j is y, column i is x
  std::vector<float> scaled;   // raw / max(raw): the kernel texture's values, in [0, 1]
  double max_raw = 0.0;

  // Kernel coordinate of table node i (eq. 4: x_min + i * dx).
  double node(int i) const { return -extent + 2.0 * extent * i / (size - 1); }
};

// The Gaussian kernel of eq. 3.
double gaussian_kernel(double x, double y, double z);

// Composite quadrature of exp(-z^2/2) over [-extent, extent] with `intervals` intervals.
// Simpson's rule needs an even number of intervals (std::invalid_argument otherwise).
double integrate_kernel_profile(int intervals, QuadratureRule rule, double extent);

// Closed form of the footprint: integral over z in [-e, e] of h(x, y, z)
//   = sqrt(2 pi) * erf(e / sqrt 2) * exp(-(x^2 + y^2) / 2).
double footprint_closed_form(double x, double y, double extent = 3.0);

// Builds the table of eq. 4. size >= 2, intervals >= 1 (std::invalid_argument otherwise).
FootprintTable make_footprint_table(int size, int intervals,
                                    QuadratureRule rule = QuadratureRule::trapezoid,
                                    double extent = 3.0);

// The scaled table sampled at kernel coordinates (x, y) with bilinear filtering, exactly as a
// GL_LINEAR texture lookup at the matching texture coordinate does (clamped at the border).
double sample_footprint_bilinear(const FootprintTable& table, double x, double y);

// Texture coordinate in [0, 1] at which a GL texture of the table (one texel per node) holds the
// node value for kernel coordinate x: texel centres sit at (i + 0.5) / size.
double footprint_texcoord(const FootprintTable& table, double x);

struct FootprintError {
  // Raw table integrals against the closed form at every node: the quadrature error.
  double max_abs_error = 0.0;
  // Scaled table against the closed form scaled the same way (by its largest node value):
  // zero up to rounding, because the kernel is separable (see above).
  double max_abs_error_scaled = 0.0;
  // Bilinear reconstruction of the scaled table against exp(-(x^2+y^2)/2) (the footprint
  // normalised to 1 at its centre) on a dense grid of points: the error the renderer sees.
  double max_abs_error_sampled = 0.0;
  // The raw table (not scaled) sampled the same way against the closed form itself, relative to
  // the closed form's peak: quadrature and reconstruction error together, which is what a table
  // used without the paper's scaling would carry (`pyro chart footprint` plots it).
  double max_rel_error_raw_sampled = 0.0;
  int sample_grid = 0;
};

FootprintError measure_footprint_error(const FootprintTable& table, int sample_grid = 481);

// Smallest table size whose sampled error (max_abs_error_sampled) is at most `max_error`,
// searched over 2..4096. The error falls as the square of the node spacing.
int footprint_size_for_error(double max_error, int intervals = 100,
                             QuadratureRule rule = QuadratureRule::trapezoid);

}  // namespace pyro
