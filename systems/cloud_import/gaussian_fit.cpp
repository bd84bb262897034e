#include "systems/cloud_import/gaussian_fit.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <numeric>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "engine/math/symmetric_eigen.h"
#include "systems/cloud_import/light_sweep.h"
#include "systems/reference/parallel_rows.h"

namespace pyro {

namespace {

constexpr float kExtent2 = kAnisotropicExtent * kAnisotropicExtent;

// The grid's box grown by `margin` voxels on every side, as a dense array of floats (x fastest).
// Local index x (0 = the first stored voxel) is element x + margin.
struct FieldBox {
  int margin = 0;
  int n[3] = {0, 0, 0};
  size_t at(int x, int y, int z) const {
    return (size_t(z + margin) * n[1] + size_t(y + margin)) * n[0] + size_t(x + margin);
  }
  size_t size() const { return size_t(n[0]) * n[1] * n[2]; }
  int lo() const { return -margin; }
  int hi(int a) const { return n[a] - margin - 1; }  // last local index on axis a
};

FieldBox field_box(const DenseGrid& grid, int margin) {
  FieldBox b;
  b.margin = margin;
  for (int a = 0; a < 3; ++a) b.n[a] = grid.dims[a] + 2 * margin;
  return b;
}

// -rho over the grown box: the residual before any Gaussian is added.
std::vector<float> negative_density(const DenseGrid& grid, const FieldBox& box) {
  std::vector<float> r(box.size(), 0.0f);
  for (int z = 0; z < grid.dims[2]; ++z)
    for (int y = 0; y < grid.dims[1]; ++y)
      for (int x = 0; x < grid.dims[0]; ++x) r[box.at(x, y, z)] = -grid.at(x, y, z);
  return r;
}

// The range of planes [z0, z1] a Gaussian reaches (its truncation ellipsoid's box: half-extent
// 3 sqrt(Sigma_zz)), clipped to the grown box; empty when z0 > z1.
void plane_range(const GridGaussian& g, const FieldBox& box, int axis, int& lo, int& hi) {
  const glm::mat3 cov = glm::inverse(glm::transpose(g.shape) * g.shape);
  const float h = kAnisotropicExtent * std::sqrt(std::max(cov[axis][axis], 0.0f));
  lo = std::max(box.lo(), int(std::ceil(g.mean[axis] - h)));
  hi = std::min(box.hi(axis), int(std::floor(g.mean[axis] + h)));
}

// Calls f(index, u, v, e) for every voxel of plane z inside g's truncation ellipsoid: u = x - mean,
// v = A u, e = exp(-|v|^2 / 2). Along a row, |v|^2 = a t^2 + 2 (c0 . w) t + |w|^2 with t = x - mean.x,
// c0 = A's first column, a = |c0|^2 and w = A (0, dy, dz); the row's voxels inside are the t
// between its roots. From one voxel to the next, e is multiplied by exp(-(c0 . v) - a / 2), and
// that factor by exp(-a): two products a voxel instead of an exponential.
template <class F>
void visit_plane(const GridGaussian& g, const FieldBox& box, int z, int ylo, int yhi, F&& f) {
  const glm::vec3 c0 = g.shape[0], c1 = g.shape[1], c2 = g.shape[2];
  const float a = glm::dot(c0, c0);
  const float step_ratio = std::exp(-a);
  const float dz = float(z) - g.mean.z;
  for (int y = ylo; y <= yhi; ++y) {
    const float dy = float(y) - g.mean.y;
    const glm::vec3 w = c1 * dy + c2 * dz;
    const float b = glm::dot(c0, w), c = glm::dot(w, w) - kExtent2;
    const float disc = b * b - a * c;
    if (disc < 0.0f) continue;
    const float root = std::sqrt(disc);
    const int xlo = std::max(box.lo(), int(std::ceil(g.mean.x + (-b - root) / a)));
    const int xhi = std::min(box.hi(0), int(std::floor(g.mean.x + (-b + root) / a)));
    if (xlo > xhi) continue;
    size_t index = box.at(xlo, y, z);
    float t = float(xlo) - g.mean.x;
    glm::vec3 v = c0 * t + w;
    float e = std::exp(-0.5f * glm::dot(v, v));
    float ratio = std::exp(-glm::dot(c0, v) - 0.5f * a);
    for (int x = xlo; x <= xhi; ++x, ++index) {
      f(index, glm::vec3(t, dy, dz), v, e);
      e *= ratio;
      ratio *= step_ratio;
      t += 1.0f;
      v += c0;
    }
  }
}

template <class F>
void visit(const GridGaussian& g, const FieldBox& box, F&& f) {
  int zlo, zhi, ylo, yhi;
  plane_range(g, box, 2, zlo, zhi);
  plane_range(g, box, 1, ylo, yhi);
  for (int z = zlo; z <= zhi; ++z) visit_plane(g, box, z, ylo, yhi, f);
}

// The residual f - rho over the grown box. Each plane adds its Gaussians in index order on one
// thread, so the sums do not depend on the thread count.
std::vector<float> residual(const DenseGrid& grid, const std::vector<GridGaussian>& gs,
                            const FieldBox& box, int threads) {
  std::vector<float> r = negative_density(grid, box);
  std::vector<std::vector<uint32_t>> planes(box.n[2]);
  for (uint32_t i = 0; i < gs.size(); ++i) {
    int zlo, zhi;
    plane_range(gs[i], box, 2, zlo, zhi);
    for (int z = zlo; z <= zhi; ++z) planes[z + box.margin].push_back(i);
  }
  parallel_rows(box.n[2], threads, [&](int plane) {
    for (const uint32_t i : planes[plane]) {
      const GridGaussian& g = gs[i];
      int ylo, yhi;
      plane_range(g, box, 1, ylo, yhi);
      visit_plane(g, box, plane - box.margin, ylo, yhi,
                  [&](size_t q, const glm::vec3&, const glm::vec3&, float e) { r[q] += g.peak * e; });
    }
  });
  return r;
}

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

// Keeps every axis's sigma within [min_sigma, max_sigma]: A = diag(1 / sigma) V^T from the
// eigen-decomposition of A^T A, clamped.
void clamp_shape(GridGaussian& g, float min_sigma, float max_sigma) {
  const glm::dmat3 a(g.shape);
  const SymmetricEigen e = symmetric_eigen(glm::transpose(a) * a);
  const double lo = 1.0 / (double(max_sigma) * max_sigma), hi = 1.0 / (double(min_sigma) * min_sigma);
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

void keep_inside(GridGaussian& g, const FieldBox& box) {
  for (int a = 0; a < 3; ++a) g.mean[a] = std::clamp(g.mean[a], float(box.lo()), float(box.hi(a)));
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
      keep_inside(gs[i], box);
      if (step % 8 == 7 || step == opt.steps - 1) clamp_shape(gs[i], opt.min_sigma, opt.max_sigma);
    });
    r = residual(grid, gs, box, opt.threads);
    ++rep.steps;
  }
  rep.rmse_after = active_rmse(grid, box, r);
  rep.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return rep;
}

namespace {

// Each Gaussian's share of the squared residual: sum over its voxels of (its value there / the
// sum's value there) r^2.
std::vector<double> residual_shares(const DenseGrid& grid, const std::vector<GridGaussian>& gs,
                                    const FieldBox& box, int threads) {
  const std::vector<float> r = residual(grid, gs, box, threads);
  std::vector<float> rho = negative_density(grid, box);
  std::vector<double> share(gs.size(), 0.0);
  parallel_rows(int(gs.size()), threads, [&](int i) {
    const GridGaussian& g = gs[i];
    double s = 0.0;
    visit(g, box, [&](size_t q, const glm::vec3&, const glm::vec3&, float e) {
      const float f = r[q] - rho[q];  // the sum of the Gaussians there (rho[q] holds -rho)
      if (f > 0.0f) s += double(g.peak * e / f) * double(r[q]) * r[q];
    });
    share[i] = s;
  });
  return share;
}

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

DensifyReport densify_and_prune(const DenseGrid& grid, std::vector<GridGaussian>& gs, double split_fraction,
                                double depth_per_density_voxel, double prune_depth,
                                const GaussianFitOptions& opt) {
  DensifyReport rep;
  const FieldBox box = field_box(grid, opt.margin);
  const std::vector<double> share = residual_shares(grid, gs, box, opt.threads);
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

std::vector<AnisotropicGaussian> lit_world_gaussians(const DenseGrid& grid, const std::vector<GridGaussian>& gs,
                                                     const VolumeMedium& medium, int threads) {
  const FieldBox box = field_box(grid, 0);
  const std::vector<float> depth = light_optical_depth_sweep(grid, medium, threads);
  std::vector<AnisotropicGaussian> out(gs.size());
  parallel_rows(int(gs.size()), threads, [&](int i) {
    const GridGaussian& g = gs[i];
    double wsum = 0.0, tsum = 0.0;
    visit(g, box, [&](size_t q, const glm::vec3&, const glm::vec3&, float e) {
      const double w = double(e) * grid.values[q];
      wsum += w;
      tsum += w * std::exp(-double(depth[q]));
    });
    const double t = wsum > 0.0 ? tsum / wsum : 1.0;
    out[i] = world_gaussian(grid, g, medium.extinction);
    out[i].color = glm::vec3(glm::clamp(medium.albedo * (medium.light_color * t + medium.ambient), glm::dvec3(0.0),
                                        glm::dvec3(1.0)));
  });
  return out;
}

}  // namespace pyro
