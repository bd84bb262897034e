#include "systems/runtime/cloud_import/gaussian_fit.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <numeric>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "engine/math/symmetric_eigen.h"
#include "systems/runtime/cloud_import/gaussian_field.h"
#include "systems/runtime/reference/parallel_rows.h"

namespace pyro {

using namespace gaussian_field;

namespace {

double active_rmse(const DenseGrid& grid, const FieldBox& box, const std::vector<float>& r) {
  double sum = 0.0;
  uint64_t count = 0;
  for (int z = 0; z < grid.dims[2]; ++z)
    for (int y = 0; y < grid.dims[1]; ++y)
      for (int x = 0; x < grid.dims[0]; ++x) {
        if (grid.at(x, y, z) == 0.0f) continue;
        const double e = r[box.at(x, y, z)];
        sum += e * e;
        ++count;
      }
  return count ? std::sqrt(sum / double(count)) : 0.0;
}

// One Gaussian's parameters as Adam sees them: mean (3), A column by column (9), ln peak (1).
constexpr int kParams = 13;
using Params = std::array<float, kParams>;

Params gradient(const GridGaussian& g, const FieldBox& box, const std::vector<float>& r) {
  float g_peak = 0.0f;
  glm::vec3 sv(0.0f);
  glm::mat3 ga(0.0f);  // -sum w v u^T: column j is -sum w v u_j
  visit(g, box, [&](size_t q, const glm::vec3& u, const glm::vec3& v, float e) {
    const float w = r[q] * g.peak * e;
    g_peak += w;
    sv += w * v;
    ga[0] -= (w * u.x) * v;
    ga[1] -= (w * u.y) * v;
    ga[2] -= (w * u.z) * v;
  });
  const glm::vec3 g_mean = glm::transpose(g.shape) * sv;
  Params p{};
  for (int a = 0; a < 3; ++a) p[a] = g_mean[a];
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) p[3 + 3 * c + k] = ga[c][k];
  p[12] = g_peak;
  return p;
}

// Keeps every axis's sigma within [min_sigma, max_sigma] and within max_aspect of the thinnest:
// A = diag(1 / sigma) V^T from the eigen-decomposition of A^T A, clamped. Needles and sheets
// much longer than they are thin fit the field between voxel centres no better, but seen along
// their length they draw bright streaks that no view of the fit was measured from.
void clamp_shape(GridGaussian& g, float min_sigma, float max_sigma, float max_aspect) {
  const glm::dmat3 a(g.shape);
  const SymmetricEigen e = symmetric_eigen(glm::transpose(a) * a);  // 1 / sigma^2, largest first
  // No axis wider than max_aspect times the thinnest: the widest's 1 / sigma^2 is at least the
  // thinnest's over max_aspect^2.
  const double lo = std::max(1.0 / (double(max_sigma) * max_sigma), e.values[0] / (double(max_aspect) * max_aspect));
  const double hi = 1.0 / (double(min_sigma) * min_sigma);
  bool inside = true;
  for (int i = 0; i < 3; ++i) inside = inside && e.values[i] >= lo && e.values[i] <= hi;
  if (inside) return;
  glm::dmat3 d(0.0);
  for (int i = 0; i < 3; ++i) d[i][i] = std::sqrt(std::clamp(e.values[i], lo, hi));
  g.shape = glm::mat3(d * glm::transpose(e.vectors));
}

struct Adam {
  std::vector<Params> m, v;
  std::vector<float> shape_scale;  // |A|_F / sqrt 3 at the start: A's step is relative to it
  static constexpr float b1 = 0.9f, b2 = 0.999f, eps = 1e-12f;
};

void adam_step(GridGaussian& g, const Params& grad, Adam& adam, size_t i, int step, float rate,
               const GaussianFitOptions& opt) {
  const float c1 = 1.0f - std::pow(Adam::b1, float(step + 1));
  const float c2 = 1.0f - std::pow(Adam::b2, float(step + 1));
  Params& m = adam.m[i];
  Params& v = adam.v[i];
  Params d{};
  for (int k = 0; k < kParams; ++k) {
    m[k] = Adam::b1 * m[k] + (1.0f - Adam::b1) * grad[k];
    v[k] = Adam::b2 * v[k] + (1.0f - Adam::b2) * grad[k] * grad[k];
    d[k] = (m[k] / c1) / (std::sqrt(v[k] / c2) + Adam::eps);
  }
  for (int a = 0; a < 3; ++a) g.mean[a] -= rate * opt.mean_step * d[a];
  const float shape_rate = rate * opt.shape_step * adam.shape_scale[i];
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) g.shape[c][k] -= shape_rate * d[3 + 3 * c + k];
  g.peak *= std::exp(-rate * opt.peak_step * d[12]);
}

// Keeps the whole truncation ellipsoid inside the grown box, where the loss sees it: the mean is
// clamped into the box, and where the ellipsoid's extent along an axis, 3 sqrt(Sigma_aa), reaches
// past the box, the covariance is scaled down until it does not. A Gaussian that left the box
// would be free there, and the renderer would draw what the fit never saw (a faint needle across
// the sky, bright along its length).
void keep_inside(GridGaussian& g, const FieldBox& box) {
  for (int a = 0; a < 3; ++a) g.mean[a] = std::clamp(g.mean[a], float(box.lo()), float(box.hi(a)));
  const glm::mat3 cov = glm::inverse(glm::transpose(g.shape) * g.shape);
  float scale = 1.0f;
  for (int a = 0; a < 3; ++a) {
    const float room = std::min(g.mean[a] - float(box.lo()), float(box.hi(a)) - g.mean[a]) + 0.5f;
    const float extent = kAnisotropicExtent * std::sqrt(std::max(cov[a][a], 0.0f));
    if (extent > room) scale = std::min(scale, room / extent);
  }
  if (scale < 1.0f) g.shape /= std::max(scale, 1e-3f);
}

using Clock = std::chrono::steady_clock;

}  // namespace

double grid_gaussian_loss(const DenseGrid& grid, const std::vector<GridGaussian>& gaussians, int margin) {
  const FieldBox box = field_box(grid, margin);
  double e = 0.0;
  for (const float v : residual(grid, gaussians, box, 1)) e += 0.5 * double(v) * v;
  return e;
}

std::array<float, 13> grid_gaussian_gradient(const DenseGrid& grid, const std::vector<GridGaussian>& gaussians,
                                             size_t i, int margin) {
  const FieldBox box = field_box(grid, margin);
  return gradient(gaussians.at(i), box, residual(grid, gaussians, box, 1));
}

double grid_gaussian_rmse(const DenseGrid& grid, const std::vector<GridGaussian>& gaussians, int threads) {
  const FieldBox box = field_box(grid, 0);
  return active_rmse(grid, box, residual(grid, gaussians, box, threads));
}

GaussianFitReport fit_grid_gaussians(const DenseGrid& grid, std::vector<GridGaussian>& gs,
                                     const GaussianFitOptions& opt) {
  const auto t0 = Clock::now();
  GaussianFitReport rep;
  const FieldBox box = field_box(grid, opt.margin);
  Adam adam;
  adam.m.assign(gs.size(), Params{});
  adam.v.assign(gs.size(), Params{});
  for (const GridGaussian& g : gs)
    adam.shape_scale.push_back(std::sqrt(glm::dot(g.shape[0], g.shape[0]) + glm::dot(g.shape[1], g.shape[1]) +
                                         glm::dot(g.shape[2], g.shape[2])) / std::numbers::sqrt3_v<float>);
  std::vector<float> r = residual(grid, gs, box, opt.threads);
  rep.rmse_before = active_rmse(grid, box, r);
  for (int step = 0; step < opt.steps; ++step) {
    // The step size falls linearly to a third over the run.
    const float rate = 1.0f - (2.0f / 3.0f) * float(step) / float(std::max(1, opt.steps - 1));
    parallel_rows(int(gs.size()), opt.threads, [&](int i) {
      const Params grad = gradient(gs[i], box, r);
      adam_step(gs[i], grad, adam, size_t(i), step, rate, opt);
      if (step % 8 == 7 || step == opt.steps - 1) clamp_shape(gs[i], opt.min_sigma, opt.max_sigma, opt.max_aspect);
      keep_inside(gs[i], box);
    });
    r = residual(grid, gs, box, opt.threads);
    ++rep.steps;
  }
  rep.rmse_after = active_rmse(grid, box, r);
  rep.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return rep;
}

std::vector<double> residual_shares(const DenseGrid& grid, const std::vector<GridGaussian>& gs, int margin,
                                    int threads) {
  const FieldBox box = field_box(grid, margin);
  std::vector<float> f(box.size(), 0.0f);
  add_gaussians(f, gs, box, threads, [](uint32_t) { return 1.0f; });
  std::vector<float> r = negative_density(grid, box);
  for (size_t q = 0; q < r.size(); ++q) r[q] += f[q];
  return shares_of(gs, box, r, f, threads);
}

namespace {

// Two Gaussians in place of g along its longest axis (see densify_and_prune).
void split_gaussian(const GridGaussian& g, GridGaussian& a, GridGaussian& b) {
  const glm::dmat3 m(g.shape);
  const SymmetricEigen e = symmetric_eigen(glm::inverse(glm::transpose(m) * m));  // Sigma
  const glm::dvec3 axis = e.vectors[0];
  const double sigma = std::sqrt(e.values[0]);
  // The longest axis's variance becomes 3/4 of the parent's, so that the pair's second moment
  // along it, 3/4 sigma^2 + (sigma / 2)^2, is the parent's; the other axes keep theirs.
  glm::dmat3 d(0.0);
  d[0][0] = 1.0 / std::sqrt(0.75 * e.values[0]);
  d[1][1] = 1.0 / std::sqrt(e.values[1]);
  d[2][2] = 1.0 / std::sqrt(e.values[2]);
  a = b = g;
  a.shape = b.shape = glm::mat3(d * glm::transpose(e.vectors));
  a.mean = glm::vec3(glm::dvec3(g.mean) + 0.5 * sigma * axis);
  b.mean = glm::vec3(glm::dvec3(g.mean) - 0.5 * sigma * axis);
  // Half the mass each: a Gaussian's mass is peak (2 pi)^(3/2) sigma_1 sigma_2 sigma_3.
  a.peak = b.peak = float(g.peak / (2.0 * std::sqrt(0.75)));
}

}  // namespace

DensifyReport densify_and_prune(std::vector<GridGaussian>& gs, const std::vector<double>& share,
                                double split_fraction, double depth_per_density_voxel, double prune_depth,
                                const GaussianFitOptions& opt) {
  DensifyReport rep;
  std::vector<uint32_t> order(gs.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return share[a] > share[b]; });
  const size_t want = size_t(std::llround(split_fraction * double(gs.size())));
  std::vector<char> split(gs.size(), 0);
  for (size_t k = 0; k < order.size() && rep.split < want; ++k) {
    const uint32_t i = order[k];
    if (share[i] <= 0.0 || grid_gaussian_sigmas(gs[i])[0] <= 2.0f * opt.min_sigma) continue;
    split[i] = 1;
    ++rep.split;
  }
  std::vector<GridGaussian> out;
  out.reserve(gs.size() + rep.split);
  for (size_t i = 0; i < gs.size(); ++i) {
    const glm::vec3 sig = grid_gaussian_sigmas(gs[i]);
    const double depth = gs[i].peak * std::sqrt(2.0 * std::numbers::pi) * sig[0] * depth_per_density_voxel;
    if (depth < prune_depth) {
      ++rep.pruned;
      continue;
    }
    if (!split[i]) {
      out.push_back(gs[i]);
      continue;
    }
    GridGaussian a, b;
    split_gaussian(gs[i], a, b);
    out.push_back(a);
    out.push_back(b);
  }
  gs = std::move(out);
  return rep;
}

}  // namespace pyro
