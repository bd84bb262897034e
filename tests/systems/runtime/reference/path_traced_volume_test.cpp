// The path tracer (systems/runtime/reference/path_traced_volume.h) against an invariant (the white
// furnace), the independent single-scattering ray march, and the ordering of the orders.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/volume/sparse_grid.h"
#include "systems/runtime/reference/path_traced_volume.h"
#include "systems/runtime/reference/volume_reference.h"

namespace pyro {
namespace {

// A soft ball of density 1 − r/R in a 20³ box of voxel 0.1, centred at the world origin.
DenseGrid soft_ball() {
  DenseGrid g;
  const int n = 20;
  g.dims = {n, n, n};
  g.values.resize(size_t(n) * n * n);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double r = std::sqrt((x - 9.5) * (x - 9.5) + (y - 9.5) * (y - 9.5) + (z - 9.5) * (z - 9.5));
        g.values[(size_t(z) * n + y) * n + x] = float(std::max(0.0, 1.0 - r / 9.0));
      }
  g.index_to_world = glm::dmat4(0.1);
  g.index_to_world[3] = glm::dvec4(-0.95, -0.95, -0.95, 1.0);
  g.voxel_size = {0.1, 0.1, 0.1};
  g.active_voxels = g.values.size();
  g.max_value = 1.0f;
  return g;
}

CameraFrame small_camera_path_traced_volume() {
  return make_camera_frame({0.4f, 0.5f, 3.0f}, {0, 0, 0}, {0, 1, 0}, 45.0f, 0.1f, 100.0f, 24, 24);
}

TEST(PathTracedVolume, WhiteFurnaceIsUniform) {
  // Albedo 1, no sun, a sky and a background of radiance 1: every path ends seeing 1 with weight
  // 1, so every pixel is exactly 1 however dense the ball is.
  VolumeMedium m;
  m.extinction = 20.0;
  m.albedo = 1.0;
  m.light_color = glm::dvec3(0.0);
  m.ambient = m.background = glm::dvec3(1.0);
  PathTraceOptions o;
  o.samples_per_pixel = 8;
  o.anisotropy = 0.6;
  const PathTracedImage img = path_trace_volume(soft_ball(), small_camera_path_traced_volume(), m, o);
  EXPECT_EQ(img.truncated_paths, 0u);
  EXPECT_GT(img.scattering_events, img.paths);  // the ball is dense: paths scatter many times
  for (float v : img.image.rgb) ASSERT_NEAR(v, 1.0, 1e-9);
  EXPECT_NEAR(img.monte_carlo_error, 0.0, 1e-9);
}

// Single scattering by the path tracer against the ray march (an independent method: exact
// shadow depths marched from every voxel), with a forward lobe and the sun behind the ball.
double single_scattering_gap(double g, double& mc_error) {
  VolumeMedium m;
  m.extinction = 3.0;
  m.albedo = 0.8;
  m.light_direction = {-0.3, -0.4, 1.0};  // towards the camera: the forward lobe shows
  m.ambient = {0.1, 0.12, 0.15};  // single scattering adds it unshadowed, as the ray march does
  const DenseGrid grid = soft_ball();
  PathTraceOptions o;
  o.samples_per_pixel = 1024;
  o.max_scattering = 1;
  o.anisotropy = g;
  const PathTracedImage traced = path_trace_volume(grid, small_camera_path_traced_volume(), m, o);
  mc_error = traced.monte_carlo_error;
  SunScattering sun;
  sun.anisotropy = g;
  const RgbImage marched = render_volume_reference(grid, light_optical_depth(grid, m, 0.25),
                                                   small_camera_path_traced_volume(), m, 0.25, 0, nullptr, sun);
  return image_rmse(traced.image, marched);
}

TEST(PathTracedVolume, SingleScatteringMatchesTheRayMarch) {
  for (double g : {0.0, 0.6}) {
    double mc = 0.0;
    const double gap = single_scattering_gap(g, mc);
    EXPECT_LT(mc, 0.015) << g;
    EXPECT_LT(gap, 3.0 * mc + 0.002) << "g " << g << " Monte Carlo error " << mc;
    std::printf("g %.1f: gap %.5f, Monte Carlo error %.5f\n", g, gap, mc);
  }
}

TEST(PathTracedVolume, MultipleScatteringBrightensAndConverges) {
  VolumeMedium m;
  m.extinction = 6.0;
  m.albedo = 0.95;
  m.ambient = glm::dvec3(0.0);
  m.background = glm::dvec3(0.0);
  PathTraceOptions o;
  o.samples_per_pixel = 64;
  o.max_scattering = 1;
  const PathTracedImage single = path_trace_volume(soft_ball(), small_camera_path_traced_volume(), m, o);
  o.max_scattering = 100000;
  const PathTracedImage multiple = path_trace_volume(soft_ball(), small_camera_path_traced_volume(), m, o);
  double s = 0.0, ms = 0.0;
  for (size_t i = 0; i < single.image.rgb.size(); ++i) {
    s += single.image.rgb[i];
    ms += multiple.image.rgb[i];
  }
  EXPECT_GT(ms, 1.3 * s);  // at albedo 0.95 and depth ~6, higher orders add a lot
  EXPECT_EQ(multiple.truncated_paths, 0u);
  // Quadrupling the samples halves the Monte Carlo error (1/√N), to 15 %.
  o.samples_per_pixel = 256;
  const PathTracedImage more = path_trace_volume(soft_ball(), small_camera_path_traced_volume(), m, o);
  EXPECT_NEAR(more.monte_carlo_error / multiple.monte_carlo_error, 0.5, 0.075);
  EXPECT_LT(image_rmse(more.image, multiple.image), 3.0 * multiple.monte_carlo_error);
}

TEST(PathTracedVolume, SparseBricksTraceTheSameImage) {
  VolumeMedium m;
  m.extinction = 6.0;
  PathTraceOptions o;
  o.samples_per_pixel = 4;
  const DenseGrid dense = soft_ball();
  const PathTracedImage a = path_trace_volume(dense, small_camera_path_traced_volume(), m, o);
  const PathTracedImage b = path_trace_volume(sparse_from_dense(dense), small_camera_path_traced_volume(), m, o);
  EXPECT_EQ(a.image.rgb, b.image.rgb);
  EXPECT_EQ(a.scattering_events, b.scattering_events);
}

}  // namespace
}  // namespace pyro
