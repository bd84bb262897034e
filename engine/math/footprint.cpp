#include "engine/math/footprint.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pyro {

const char* quadrature_rule_name(QuadratureRule rule) {
  switch (rule) {
    case QuadratureRule::trapezoid: return "trapezoid";
    case QuadratureRule::simpson: return "simpson";
    case QuadratureRule::midpoint: return "midpoint";
  }
  return "?";
}

bool parse_quadrature_rule(const std::string& name, QuadratureRule& rule) {
  for (QuadratureRule r :
       {QuadratureRule::trapezoid, QuadratureRule::simpson, QuadratureRule::midpoint}) {
    if (name == quadrature_rule_name(r)) {
      rule = r;
      return true;
    }
  }
  return false;
}

double gaussian_kernel(double x, double y, double z) {
  return std::exp(-(x * x + y * y + z * z) / 2.0);  // Johnson & McAllister eq. 3
}

namespace {

// Weights and abscissae of the composite rule over [-extent, extent], so that the table loop
// evaluates the kernel in 3D at each abscissa (eq. 4) rather than reusing the 1D profile.
struct QuadratureNodes {
  std::vector<double> z, w;
};

QuadratureNodes composite_nodes(int intervals, QuadratureRule rule, double extent) {
  if (intervals < 1) throw std::invalid_argument("quadrature needs at least one interval");
  if (rule == QuadratureRule::simpson && intervals % 2 != 0)
    throw std::invalid_argument("Simpson's rule needs an even number of intervals");
  QuadratureNodes q;
  const double a = -extent;
  const double h = 2.0 * extent / intervals;
  switch (rule) {
    case QuadratureRule::trapezoid:
      for (int k = 0; k <= intervals; ++k) {
        q.z.push_back(a + k * h);
        q.w.push_back((k == 0 || k == intervals) ? h / 2.0 : h);
      }
      break;
    case QuadratureRule::simpson:
      for (int k = 0; k <= intervals; ++k) {
        q.z.push_back(a + k * h);
        const double c = (k == 0 || k == intervals) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        q.w.push_back(c * h / 3.0);
      }
      break;
    case QuadratureRule::midpoint:
      for (int k = 0; k < intervals; ++k) {
        q.z.push_back(a + (k + 0.5) * h);
        q.w.push_back(h);
      }
      break;
  }
  return q;
}

}  // namespace

double integrate_kernel_profile(int intervals, QuadratureRule rule, double extent) {
  const QuadratureNodes q = composite_nodes(intervals, rule, extent);
  double sum = 0.0;
  for (size_t k = 0; k < q.z.size(); ++k) sum += q.w[k] * std::exp(-q.z[k] * q.z[k] / 2.0);
  return sum;
}

double footprint_closed_form(double x, double y, double extent) {
  const double line = std::sqrt(2.0 * std::numbers::pi) * std::erf(extent / std::numbers::sqrt2);
  return line * std::exp(-(x * x + y * y) / 2.0);
}

FootprintTable make_footprint_table(int size, int intervals, QuadratureRule rule,
                                    double extent) {
  if (size < 2) throw std::invalid_argument("footprint table size must be at least 2");
  if (!(extent > 0.0)) throw std::invalid_argument("footprint extent must be positive");
  const QuadratureNodes q = composite_nodes(intervals, rule, extent);
  FootprintTable t;
  t.size = size;
  t.intervals = intervals;
  t.extent = extent;
  t.rule = rule;
  t.raw.resize(static_cast<size_t>(size) * size);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      double sum = 0.0;  // eq. 4: integral of h along the viewing direction at node (i, j)
      for (size_t k = 0; k < q.z.size(); ++k)
        sum += q.w[k] * gaussian_kernel(t.node(i), t.node(j), q.z[k]);
      t.raw[static_cast<size_t>(j) * size + i] = sum;
    }
  }
  t.max_raw = *std::max_element(t.raw.begin(), t.raw.end());
  t.scaled.resize(t.raw.size());
  for (size_t k = 0; k < t.raw.size(); ++k) t.scaled[k] = static_cast<float>(t.raw[k] / t.max_raw);
  return t;
}

double footprint_texcoord(const FootprintTable& table, double x) {
  const double s = (x + table.extent) / (2.0 * table.extent);  // 0 at node 0, 1 at node size-1
  return (0.5 + s * (table.size - 1)) / table.size;
}

double sample_footprint_bilinear(const FootprintTable& t, double x, double y) {
  // Continuous node coordinate, clamped like GL_CLAMP_TO_EDGE.
  auto coord = [&](double v) {
    const double c = (v + t.extent) / (2.0 * t.extent) * (t.size - 1);
    return std::clamp(c, 0.0, static_cast<double>(t.size - 1));
  };
  const double cx = coord(x), cy = coord(y);
  const int i0 = std::min(static_cast<int>(cx), t.size - 2);
  const int j0 = std::min(static_cast<int>(cy), t.size - 2);
  const double fx = cx - i0, fy = cy - j0;
  auto at = [&](int i, int j) { return static_cast<double>(t.scaled[static_cast<size_t>(j) * t.size + i]); };
  return (1 - fx) * (1 - fy) * at(i0, j0) + fx * (1 - fy) * at(i0 + 1, j0) +
         (1 - fx) * fy * at(i0, j0 + 1) + fx * fy * at(i0 + 1, j0 + 1);
}

FootprintError measure_footprint_error(const FootprintTable& t, int sample_grid) {
  FootprintError e;
  e.sample_grid = sample_grid;
  double max_closed = 0.0;
  for (int j = 0; j < t.size; ++j)
    for (int i = 0; i < t.size; ++i)
      max_closed = std::max(max_closed, footprint_closed_form(t.node(i), t.node(j), t.extent));
  for (int j = 0; j < t.size; ++j) {
    for (int i = 0; i < t.size; ++i) {
      const double exact = footprint_closed_form(t.node(i), t.node(j), t.extent);
      const size_t k = static_cast<size_t>(j) * t.size + i;
      e.max_abs_error = std::max(e.max_abs_error, std::abs(t.raw[k] - exact));
      e.max_abs_error_scaled =
          std::max(e.max_abs_error_scaled, std::abs(t.raw[k] / t.max_raw - exact / max_closed));
    }
  }
  const double peak = footprint_closed_form(0.0, 0.0, t.extent);
  for (int j = 0; j < sample_grid; ++j) {
    for (int i = 0; i < sample_grid; ++i) {
      const double x = -t.extent + 2.0 * t.extent * i / (sample_grid - 1);
      const double y = -t.extent + 2.0 * t.extent * j / (sample_grid - 1);
      const double exact = std::exp(-(x * x + y * y) / 2.0);
      const double sampled = sample_footprint_bilinear(t, x, y);
      e.max_abs_error_sampled = std::max(e.max_abs_error_sampled, std::abs(sampled - exact));
      e.max_rel_error_raw_sampled =
          std::max(e.max_rel_error_raw_sampled,
                   std::abs(sampled * t.max_raw - footprint_closed_form(x, y, t.extent)) / peak);
    }
  }
  return e;
}

int footprint_size_for_error(double max_error, int intervals, QuadratureRule rule) {
  // The sampled error falls monotonically (as h^2) with size once size is past a handful of
  // nodes, so a doubling search followed by bisection finds the smallest size.
  auto error_at = [&](int n) {
    return measure_footprint_error(make_footprint_table(n, intervals, rule), 241)
        .max_abs_error_sampled;
  };
  int hi = 8;
  while (hi < 4096 && error_at(hi) > max_error) hi *= 2;
  hi = std::min(hi, 4096);
  int lo = hi / 2;
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (error_at(mid) > max_error) lo = mid; else hi = mid;
  }
  return hi;
}

}  // namespace pyro
