// Fitting anisotropic Gaussians to grids: a grid sampled from known Gaussians is recovered from a
// perturbed start, the fit lowers the field error of the octree's particles on hard shapes, the
// result does not depend on the thread count, a split keeps mass and second moments, and the
// octree's particles become grid and world Gaussians with the same centre, size and optical depth.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>

#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/gaussian_fit.h"

namespace pyro {
namespace {

DenseGrid empty_grid(int nx, int ny, int nz) {
  DenseGrid g;
  g.dims = {nx, ny, nz};
  g.values.assign(size_t(nx) * ny * nz, 0.0f);
  g.index_to_world = glm::dmat4(1.0);
  return g;
}

void finish(DenseGrid& g) {
  g.active_voxels = 0;
  g.max_value = 0.0f;
  for (const float v : g.values) {
    g.active_voxels += v != 0.0f;
    g.max_value = std::max(g.max_value, v);
  }
}

// The grid's values at voxel centres are the sum of the given Gaussians (truncated at 3 sigma),
// evaluated directly from their definition.
DenseGrid grid_of(const std::vector<GridGaussian>& gs, int n) {
  DenseGrid g = empty_grid(n, n, n);
  size_t i = 0;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x, ++i)
        for (const GridGaussian& s : gs) {
          const glm::vec3 v = s.shape * (glm::vec3(x, y, z) - s.mean);
          const float m2 = glm::dot(v, v);
          if (m2 <= 9.0f) g.values[i] += s.peak * std::exp(-0.5f * m2);
        }
  finish(g);
  return g;
}

GridGaussian rotated(glm::vec3 mean, glm::vec3 sigma, glm::quat q, float peak) {
  const glm::mat3 r = glm::mat3_cast(q);
  GridGaussian g;
  g.mean = mean;
  g.shape = glm::mat3(1.0f / sigma.x, 0, 0, 0, 1.0f / sigma.y, 0, 0, 0, 1.0f / sigma.z) * glm::transpose(r);
  g.peak = peak;
  return g;
}

TEST(GaussianFit, RecoversAKnownAnisotropicGaussianFromAPerturbedStart) {
  const glm::quat q = glm::angleAxis(0.6f, glm::normalize(glm::vec3(1, 2, 0.5f)));
  const GridGaussian truth = rotated({15.3f, 16.1f, 14.7f}, {5.0f, 2.0f, 1.2f}, q, 0.8f);
  const DenseGrid grid = grid_of({truth}, 32);
  std::vector<GridGaussian> gs = {rotated({16, 16, 16}, {3, 3, 3}, glm::quat(1, 0, 0, 0), 0.4f)};
  GaussianFitOptions opt;
  opt.steps = 400;
  opt.threads = 2;
  const GaussianFitReport rep = fit_grid_gaussians(grid, gs, opt);
  EXPECT_LT(rep.rmse_after, 0.02 * rep.rmse_before);
  EXPECT_NEAR(gs[0].mean.x, truth.mean.x, 0.05);
  EXPECT_NEAR(gs[0].mean.y, truth.mean.y, 0.05);
  EXPECT_NEAR(gs[0].mean.z, truth.mean.z, 0.05);
  EXPECT_NEAR(gs[0].peak, truth.peak, 0.02);
  // The inverse covariance, which the shape's rotation freedom leaves unique.
  const glm::mat3 got = glm::transpose(gs[0].shape) * gs[0].shape;
  const glm::mat3 want = glm::transpose(truth.shape) * truth.shape;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(got[c][r], want[c][r], 0.03 * want[0][0] + 0.01) << c << "," << r;
}

TEST(GaussianFit, GradientsAgreeWithFiniteDifferencesOfTheLoss) {
  const glm::quat q = glm::angleAxis(0.9f, glm::normalize(glm::vec3(0.3f, 1, 0.7f)));
  const DenseGrid grid = grid_of({rotated({9.2f, 10.4f, 9.7f}, {3.0f, 1.6f, 1.1f}, q, 0.7f)}, 20);
  // The truncation at 3 sigma makes the loss jump by e^-4.5 peak r where a voxel crosses the
  // ellipsoid, which the finite differences see and the gradient leaves out: hence 5 %.
  // Two overlapping Gaussians off the truth, one rotated, so that every term of the gradient
  // (mean, each entry of A, peak) is far from zero.
  std::vector<GridGaussian> gs = {
      rotated({9.6f, 10.0f, 10.1f}, {2.2f, 1.9f, 1.3f}, glm::angleAxis(0.5f, glm::vec3(0, 0, 1)), 0.5f),
      rotated({8.0f, 11.0f, 9.0f}, {1.5f, 1.5f, 1.5f}, glm::quat(1, 0, 0, 0), 0.3f)};
  const std::array<float, 13> g = grid_gaussian_gradient(grid, gs, 0, 2);
  const auto loss_with = [&](int k, double h) {
    std::vector<GridGaussian> moved = gs;
    GridGaussian& m = moved[0];
    if (k < 3) m.mean[k] += float(h);
    else if (k < 12) m.shape[(k - 3) / 3][(k - 3) % 3] += float(h);
    else m.peak *= float(std::exp(h));
    return grid_gaussian_loss(grid, moved, 2);
  };
  for (int k = 0; k < 13; ++k) {
    const double h = 1e-3;
    const double fd = (loss_with(k, h) - loss_with(k, -h)) / (2.0 * h);
    EXPECT_NEAR(g[k], fd, 0.05 * std::abs(fd) + 2e-3) << "parameter " << k;
  }
}

DenseGrid hard_box() {
  DenseGrid g = empty_grid(21, 21, 21);
  std::fill(g.values.begin(), g.values.end(), 1.0f);
  finish(g);
  return g;
}

TEST(GaussianFit, LowersTheFieldErrorOfTheOctreeParticlesOnAHardBox) {
  const DenseGrid grid = hard_box();
  CloudImportOptions io;
  io.medium.extinction = 8.0 / 21.0;
  io.tau_tolerance = 0.12;
  const std::vector<GaussianParticle> ps = import_cloud(grid, io);
  std::vector<GridGaussian> gs = grid_gaussians_from_particles(grid, ps, io.medium);
  GaussianFitOptions opt;
  opt.steps = 80;
  const GaussianFitReport rep = fit_grid_gaussians(grid, gs, opt);
  EXPECT_NEAR(rep.rmse_before, grid_gaussian_rmse(grid, grid_gaussians_from_particles(grid, ps, io.medium)), 1e-6);
  EXPECT_LT(rep.rmse_after, 0.6 * rep.rmse_before);
  EXPECT_NEAR(rep.rmse_after, grid_gaussian_rmse(grid, gs), 1e-6);
}

// Whatever the fit does, every Gaussian stays where the loss sees it (its ellipsoid inside the box
// grown by the margin) and no axis is more than max_aspect times another: a Gaussian outside would
// be drawn where the fit never looked.
TEST(GaussianFit, EveryEllipsoidStaysInsideTheFittedBoxAndWithinTheAspectBound) {
  DenseGrid grid = empty_grid(24, 12, 16);
  for (int z = 3; z < 13; ++z)
    for (int y = 2; y < 10; ++y)
      for (int x = 0; x < 24; ++x) grid.values[(size_t(z) * 12 + y) * 24 + x] = x < 20 ? 0.8f : 0.0f;
  finish(grid);
  // A start that reaches far past the box: wide, thin Gaussians.
  std::vector<GridGaussian> gs = {rotated({4, 6, 8}, {30.0f, 0.5f, 0.5f}, glm::quat(1, 0, 0, 0), 0.5f),
                                  rotated({15, 6, 8}, {6.0f, 6.0f, 0.4f}, glm::angleAxis(0.7f, glm::vec3(0, 1, 0)), 0.5f)};
  GaussianFitOptions opt;
  opt.steps = 16;
  fit_grid_gaussians(grid, gs, opt);
  for (const GridGaussian& g : gs) {
    const glm::mat3 cov = glm::inverse(glm::transpose(g.shape) * g.shape);
    for (int a = 0; a < 3; ++a) {
      const float h = 3.0f * std::sqrt(cov[a][a]);
      EXPECT_GE(g.mean[a] - h, -opt.margin - 0.5f - 1e-3f) << a;
      EXPECT_LE(g.mean[a] + h, grid.dims[a] - 1 + opt.margin + 0.5f + 1e-3f) << a;
    }
    const glm::vec3 sig = grid_gaussian_sigmas(g);
    EXPECT_LE(sig[0], opt.max_aspect * sig[2] * 1.001f);
  }
}

TEST(GaussianFit, ResultsDoNotDependOnTheThreadCount) {
  const DenseGrid grid = hard_box();
  CloudImportOptions io;
  io.medium.extinction = 0.4;
  io.tau_tolerance = 0.2;
  const std::vector<GridGaussian> start =
      grid_gaussians_from_particles(grid, import_cloud(grid, io), io.medium);
  std::vector<std::vector<GridGaussian>> results;
  for (const int threads : {1, 2, 4}) {
    std::vector<GridGaussian> gs = start;
    GaussianFitOptions opt;
    opt.steps = 12;
    opt.threads = threads;
    fit_grid_gaussians(grid, gs, opt);
    densify_and_prune(gs, residual_shares(grid, gs, opt.margin, threads), 0.2, 0.4, 1e-3, opt);
    results.push_back(gs);
  }
  for (size_t t = 1; t < results.size(); ++t) {
    ASSERT_EQ(results[t].size(), results[0].size());
    EXPECT_EQ(std::memcmp(results[t].data(), results[0].data(), results[0].size() * sizeof(GridGaussian)), 0);
  }
}

// Mass and second moment about the mean along each axis, summed over a fine lattice.
struct Moments {
  double mass = 0.0;
  glm::dvec3 mean{0.0}, second{0.0};
};

Moments moments(const std::vector<GridGaussian>& gs) {
  Moments m;
  const double h = 0.1;
  for (double z = -12; z <= 12; z += h)
    for (double y = -12; y <= 12; y += h)
      for (double x = -12; x <= 12; x += h) {
        double f = 0.0;
        for (const GridGaussian& g : gs) {
          const glm::dvec3 v = glm::dmat3(g.shape) * (glm::dvec3(x, y, z) - glm::dvec3(g.mean));
          f += g.peak * std::exp(-0.5 * glm::dot(v, v));  // not truncated: the moments in closed form
        }
        m.mass += f * h * h * h;
        m.mean += f * h * h * h * glm::dvec3(x, y, z);
        m.second += f * h * h * h * glm::dvec3(x * x, y * y, z * z);
      }
  m.mean /= m.mass;
  m.second = m.second / m.mass - m.mean * m.mean;
  return m;
}

TEST(GaussianFit, ASplitKeepsMassAndSecondMoments) {
  const glm::quat q = glm::angleAxis(0.4f, glm::normalize(glm::vec3(0, 1, 1)));
  const std::vector<GridGaussian> parent = {rotated({0, 0, 0}, {2.5f, 1.0f, 0.8f}, q, 1.0f)};
  // A grid over which the parent carries all the residual, so that it is split.
  DenseGrid grid = empty_grid(16, 16, 16);
  finish(grid);
  std::vector<GridGaussian> gs = {rotated({8, 8, 8}, {2.5f, 1.0f, 0.8f}, q, 1.0f)};
  GaussianFitOptions opt;
  const DensifyReport rep = densify_and_prune(gs, residual_shares(grid, gs, opt.margin), 1.0, 1.0, 0.0, opt);
  ASSERT_EQ(rep.split, 1u);
  ASSERT_EQ(gs.size(), 2u);
  for (GridGaussian& g : gs) g.mean -= glm::vec3(8.0f);
  const Moments before = moments(parent), after = moments(gs);
  // The closed form of the parent: mass peak (2 pi)^(3/2) sigma1 sigma2 sigma3.
  EXPECT_NEAR(before.mass, std::pow(2.0 * std::numbers::pi, 1.5) * 2.5 * 1.0 * 0.8, 1e-3 * before.mass);
  EXPECT_NEAR(after.mass, before.mass, 1e-3 * before.mass);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(after.mean[a], 0.0, 1e-6);
    EXPECT_NEAR(after.second[a], before.second[a], 1e-3 * before.second[a]);
  }
}

TEST(GaussianFit, OctreeParticlesBecomeGaussiansOfTheSameCentreSizeAndDepth) {
  DenseGrid grid = hard_box();
  // A non-uniform, rotated voxel: the world particle's covariance is M Sigma M^T.
  const glm::dmat4 rot = glm::dmat4(glm::mat3_cast(glm::angleAxis(0.3, glm::dvec3(0, 0, 1))));
  grid.index_to_world = glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)) * rot *
                        glm::scale(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.5));
  grid.origin = {-4, 0, 7};
  GaussianParticle p;
  p.x = 1.5f;
  p.y = 2.5f;
  p.z = 6.0f;
  p.radius = 1.2f;  // s = 0.4
  p.density = 0.35f;
  VolumeMedium medium;
  medium.extinction = 2.0;
  const std::vector<GridGaussian> gs = grid_gaussians_from_particles(grid, {p}, medium);
  ASSERT_EQ(gs.size(), 1u);
  const AnisotropicGaussian w = world_gaussian(grid, gs[0], medium.extinction);
  EXPECT_NEAR(w.centre.x, p.x, 1e-5);
  EXPECT_NEAR(w.centre.y, p.y, 1e-5);
  EXPECT_NEAR(w.centre.z, p.z, 1e-5);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(w.scale[a], 0.4f, 1e-5);
  // Optical depth through the centre along any axis: k s sqrt(2 pi) erf(3 / sqrt 2) = -ln(1 - rho).
  const double tau0 = w.extinction * 0.4 * std::sqrt(2.0 * std::numbers::pi) * std::erf(3.0 / std::numbers::sqrt2);
  EXPECT_NEAR(tau0, -std::log(1.0 - 0.35), 1e-5);
  // In the grid, one voxel is 0.5 world units: sigma is 0.8 voxels.
  const glm::vec3 sig = grid_gaussian_sigmas(gs[0]);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(sig[a], 0.8f, 1e-5);
}

}  // namespace
}  // namespace pyro
