// The export's voxels and their measured projection error (tools/export): a particle's mass is
// kept, the grid's column depth through a Gaussian matches the closed form, the error falls as
// the voxel shrinks, the chosen size meets its target and a coarse one does not, and colour and
// temperature are the extinction-weighted means, and emission per unit length their sum.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tools/export/column_error.h"
#include "tools/export/media_voxels.h"
#include "tools/export/voxel_size_choice.h"

namespace pyro {
namespace {

MediaSample export_test_gaussian(const glm::dvec3& c, double radius, double density) {
  MediaSample s;
  s.field = clamped_gaussian(c, radius, density);
  s.detail = radius / 3.0;
  return s;
}

double voxel_mass(const MediaVoxels& v) {
  double sum = 0.0;
  for (float d : v.density) sum += d;
  return sum * std::pow(v.box.voxel, 3);
}

TEST(MediaVoxels, KeepAGaussiansMass) {
  const MediaSample s = export_test_gaussian({0.3, -0.2, 0.1}, 0.9, 0.5);
  const MediaVoxels v = voxelize_media({s}, media_box({s}, 0.06));
  // k (2 pi)^(3/2) s^3, less the tails past the cube (erf(3 / sqrt 2)^3 of it is inside).
  const double sigma = 0.3, inside = std::pow(std::erf(3.0 / std::sqrt(2.0)), 3);
  EXPECT_NEAR(voxel_mass(v), s.field.k * std::pow(2.0 * std::numbers::pi, 1.5) * std::pow(sigma, 3) * inside,
              2e-3 * voxel_mass(v));
}

TEST(MediaVoxels, ErrorFallsAsTheVoxelShrinks) {
  const std::vector<MediaSample> s = {export_test_gaussian({0, 0, 0}, 0.6, 0.6),
                                      export_test_gaussian({0.25, 0.1, 0}, 0.45, 0.4)};
  const double coarse = measure_column_error(s, voxelize_media(s, media_box(s, 0.2))).opacity_max;
  const double fine = measure_column_error(s, voxelize_media(s, media_box(s, 0.05))).opacity_max;
  EXPECT_GT(coarse, 0.02);
  // Second order: a quarter of the size, about a sixteenth of the error (up to the cube's edge).
  EXPECT_LT(fine, coarse / 6.0);
}

TEST(MediaVoxels, ChosenSizeMeetsTheTargetAndACoarserOneDoesNot) {
  std::vector<MediaSample> s;
  for (int i = 0; i < 12; ++i)
    s.push_back(export_test_gaussian({0.3 * std::cos(i), 0.2 * i - 1.0, 0.3 * std::sin(i)}, 0.5, 0.4));
  const VoxelSizeChoice c = choose_voxel_size(s, 0.01, uint64_t{1} << 24);
  ASSERT_TRUE(c.met);
  EXPECT_LE(c.error.opacity_max, 0.01);
  const double at_double = measure_column_error(s, voxelize_media(s, media_box(s, 3.0 * c.voxel))).opacity_max;
  EXPECT_GT(at_double, 0.01) << "a grid three times coarser should miss the target";
}

TEST(MediaVoxels, ATargetPastTheVoxelLimitIsSaidNotToFit) {
  const std::vector<MediaSample> s = {export_test_gaussian({0, 0, 0}, 0.5, 0.9), export_test_gaussian({40, 0, 0}, 0.5, 0.9)};
  const VoxelSizeChoice c = choose_voxel_size(s, 1e-4, 20000);
  EXPECT_FALSE(c.met);
  EXPECT_FALSE(c.fits);
}

TEST(MediaVoxels, ColourAndTemperatureAreExtinctionWeightedMeans) {
  MediaSample a = export_test_gaussian({0, 0, 0}, 0.6, 0.5), b = a;
  a.color = {1, 0, 0};
  a.temperature = 2000.0f;
  b.color = {0, 0, 1};
  b.temperature = 1000.0f;
  b.field.k = 3.0 * a.field.k;  // three times as dense: three quarters of the mix
  const MediaVoxels v = voxelize_media({a, b}, media_box({a, b}, 0.1), {true, true});
  const size_t centre = v.box.at(-v.box.origin[0], -v.box.origin[1], -v.box.origin[2]);
  EXPECT_NEAR(v.temperature[centre], 1250.0f, 0.5f);
  EXPECT_NEAR(v.color[3 * centre + 0], 0.25f, 1e-5f);
  EXPECT_NEAR(v.color[3 * centre + 2], 0.75f, 1e-5f);
  EXPECT_NEAR(v.density[centre], a.field.k * 4.0, 1e-4 * a.field.k);
}

// Absorption plus emission (Max 1995): the radiance emitted per unit length is the sum of each
// sample's extinction times its own emission, not a mean.
TEST(MediaVoxels, EmissionIsTheSumOfExtinctionTimesEmission) {
  MediaSample a = export_test_gaussian({0, 0, 0}, 0.6, 0.5), b = a;
  a.emission = {2.0f, 1.0f, 0.0f};
  b.field.k = 3.0 * a.field.k;
  const MediaVoxels v = voxelize_media({a, b}, media_box({a, b}, 0.1), {false, false, true});
  const size_t centre = v.box.at(-v.box.origin[0], -v.box.origin[1], -v.box.origin[2]);
  EXPECT_NEAR(v.emission[3 * centre + 0], 2.0 * a.field.k, 1e-4 * a.field.k);
  EXPECT_NEAR(v.emission[3 * centre + 1], 1.0 * a.field.k, 1e-4 * a.field.k);
  EXPECT_EQ(v.emission[3 * centre + 2], 0.0f);
  EXPECT_TRUE(voxelize_media({a}, media_box({a}, 0.1)).emission.empty());
}

TEST(MediaVoxels, ASpheresColumnIsTheBillboardsModel) {
  MediaSample s;
  s.field = ConeSphere{glm::dvec3(0.1, 0.0, -0.05), 1.0, 2.0};
  s.detail = 1.0 / 3.0;
  const MediaVoxels v = voxelize_media({s}, media_box({s}, 0.02));
  const ColumnError e = measure_column_error({s}, v);
  EXPECT_LT(e.opacity_max, 0.03);
  EXPECT_GT(e.depth_peak, 3.0);  // lines through the middle: 2 k (1 - d/r) sqrt(r^2 - d^2) near 4
}

}  // namespace
}  // namespace pyro
