// The importer on hand-built grids: mass is conserved, smooth regions merge, the error target
// decides the count, and lit voxels are brighter than shadowed ones.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "systems/runtime/cloud_import/cloud_import.h"

namespace pyro {
namespace {

DenseGrid box_grid(int n, float v) {
  DenseGrid g;
  g.dims = {n, n, n};
  g.values.assign(size_t(n) * n * n, v);
  g.index_to_world = glm::dmat4(1.0);
  g.active_voxels = g.values.size();
  g.max_value = v;
  return g;
}

// A particle's mass (integral of its extinction): inverse of the importer's tau0 relation.
double particle_mass(const GaussianParticle& p) {
  const double s = p.radius / 3.0, tau0 = -std::log1p(-double(p.density));
  return tau0 * 2.0 * std::numbers::pi * s * s / std::erf(3.0 / std::numbers::sqrt2);
}

TEST(CloudImport, ConservesMassAndMergesAUniformBlock) {
  const DenseGrid g = box_grid(32, 0.2f);
  CloudImportOptions opt;
  opt.medium.extinction = 0.1;
  opt.tau_tolerance = 0.2;
  CloudImportReport rep;
  const auto ps = import_cloud(g, opt, &rep);
  EXPECT_EQ(rep.active_voxels, 32u * 32u * 32u);
  EXPECT_LT(ps.size(), g.values.size() / 10);
  double mass = 0.0;
  for (const auto& p : ps) mass += particle_mass(p);
  const double want = opt.medium.extinction * 0.2 * 32 * 32 * 32;
  EXPECT_NEAR(mass, want, 1e-3 * want);
}

TEST(CloudImport, TighterErrorTargetKeepsMoreParticles) {
  DenseGrid g = box_grid(32, 0.0f);
  for (int z = 0; z < 32; ++z)
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        g.values[(size_t(z) * 32 + y) * 32 + x] = float(0.5 + 0.5 * std::sin(0.4 * x) * std::cos(0.3 * y + 0.2 * z));
  g.max_value = 1.0f;
  CloudImportOptions loose, tight;
  loose.medium.extinction = tight.medium.extinction = 0.2;
  loose.tau_tolerance = 0.3;
  tight.tau_tolerance = 0.02;
  EXPECT_LT(import_cloud(g, loose).size(), import_cloud(g, tight).size());
}

TEST(CloudImport, SelfShadowingDarkensTheFarSide) {
  const DenseGrid g = box_grid(16, 1.0f);
  CloudImportOptions opt;
  opt.medium.extinction = 0.5;
  opt.medium.light_direction = {0, -1, 0};  // from above
  opt.max_level = 0;  // one particle per voxel
  const auto ps = import_cloud(g, opt);
  ASSERT_EQ(ps.size(), 16u * 16u * 16u);
  float top = 0, bottom = 0;
  for (const auto& p : ps) {
    if (p.y == 15.0f) top = p.r;
    if (p.y == 0.0f) bottom = p.r;
  }
  EXPECT_GT(top, bottom + 0.3f);
  // The top voxel sees half a voxel of its own density: T = exp(-0.25).
  EXPECT_NEAR(top, opt.medium.albedo * (std::exp(-0.25) + opt.medium.ambient.x), 1e-3);
}

TEST(CloudImport, EmptyGridGivesNoParticles) {
  DenseGrid g;
  CloudImportReport rep;
  EXPECT_TRUE(import_cloud(g, {}, &rep).empty());
  EXPECT_EQ(rep.particles, 0u);
}

}  // namespace
}  // namespace pyro

namespace pyro {
namespace {

// The light sweep shares each slice's rows among threads and the octree its top slabs: the
// particles must be bit-for-bit the same whatever the thread count, for every sweep axis.
TEST(CloudImport, ResultsDoNotDependOnTheThreadCount) {
  DenseGrid g;
  g.dims = {37, 29, 23};
  g.values.assign(size_t(37) * 29 * 23, 0.0f);
  uint64_t state = 12345;
  for (float& v : g.values) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const float r = float(state >> 40) / float(1 << 24);
    v = r < 0.5f ? 0.0f : r;
  }
  g.index_to_world = glm::dmat4(0.5);
  g.index_to_world[3] = glm::dvec4(1.0, 2.0, 3.0, 1.0);
  g.active_voxels = g.values.size() / 2;
  g.max_value = 1.0f;
  const glm::dvec3 directions[] = {{-0.4, -1.0, -0.3}, {1.0, 0.2, -0.5}, {0.1, 0.3, 1.0}, {-0.7, 0.7, 0.1}};
  for (const glm::dvec3& dir : directions) {
    CloudImportOptions opt;
    opt.medium.extinction = 0.8;
    opt.medium.light_direction = dir;
    opt.tau_tolerance = 0.1;
    opt.threads = 1;
    const std::vector<GaussianParticle> one = import_cloud(g, opt);
    ASSERT_FALSE(one.empty());
    for (int t : {2, 3, 7}) {
      opt.threads = t;
      const std::vector<GaussianParticle> many = import_cloud(g, opt);
      ASSERT_EQ(many.size(), one.size()) << "threads " << t;
      EXPECT_EQ(std::memcmp(many.data(), one.data(), one.size() * sizeof(GaussianParticle)), 0)
          << "threads " << t << " light " << dir.x << " " << dir.y << " " << dir.z;
    }
  }
}

}  // namespace
}  // namespace pyro
