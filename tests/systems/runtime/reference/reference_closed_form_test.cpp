// The CPU reference against closed forms: one Gaussian's optical depth (erf), a uniform slab
// (Beer-Lambert, exp(-sigma d)), and the ray marcher's convergence in its step size.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/io/vdb_reader.h"
#include "systems/runtime/cloud_import/light_sweep.h"
#include "systems/runtime/reference/particle_reference.h"
#include "systems/runtime/reference/volume_reference.h"

namespace pyro {
namespace {

TEST(ParticleReference, OneGaussianOpticalDepthMatchesErfClosedForm) {
  // A ray parallel to z at miss distance d crosses the whole clamped cube; its optical depth is
  // tau0 exp(-d^2 / (2 s^2)) with tau0 = -ln(1 - rho) (the splat's centre opacity).
  const double r = 1.5, s = r / 3.0, rho = 0.6;
  for (double x0 : {0.0, 0.2, 0.7}) {
    for (double y0 : {0.0, -0.3}) {
      const double got = particle_optical_depth({0, 0, 0}, r, rho, {x0, y0, -10}, {0, 0, 1}, 0, 100);
      const double want = -std::log(1.0 - rho) * std::exp(-(x0 * x0 + y0 * y0) / (2 * s * s));
      EXPECT_NEAR(got, want, 1e-12) << x0 << " " << y0;
    }
  }
  // Half the ray (up to the centre) carries half of it: erf is odd.
  const double half = particle_optical_depth({0, 0, 0}, r, rho, {0, 0, -10}, {0, 0, 1}, 0, 10);
  EXPECT_NEAR(half, -0.5 * std::log(1.0 - rho), 1e-12);
  // A ray outside the cube sees nothing.
  EXPECT_EQ(particle_optical_depth({0, 0, 0}, r, rho, {1.6, 0, -10}, {0, 0, 1}, 0, 100), 0.0);
}

TEST(ParticleReference, OneParticleCentrePixelShowsItsDensity) {
  // The pixel through the centre: opacity 1 - exp(-tau0) = rho, over a black background.
  ParticlePool pool(1);
  ParticleInit p;
  p.radius = 1.0f;
  p.density = 0.5f;
  p.color = {1.0f, 0.5f, 0.25f};
  pool.spawn(p);
  const CameraFrame cam = make_camera_frame({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30.0f, 0.1f, 100.0f, 9, 9);
  const RgbImage img = render_particles_reference(pool, cam, glm::dvec3(0.0), 1);
  EXPECT_NEAR(img.at(4, 4)[0], 0.5, 1e-6);
  EXPECT_NEAR(img.at(4, 4)[1], 0.25, 1e-6);
  EXPECT_NEAR(img.at(4, 4)[2], 0.125, 1e-6);
}

DenseGrid uniform_slab(int nxy, int nz, float density, double voxel) {
  DenseGrid g;
  g.dims = {nxy, nxy, nz};
  g.values.assign(size_t(nxy) * nxy * nz, density);
  g.index_to_world = glm::dmat4(voxel);
  g.index_to_world[3] = glm::dvec4(0, 0, 0, 1);
  g.voxel_size = {voxel, voxel, voxel};
  g.active_voxels = g.values.size();
  g.max_value = density;
  return g;
}

TEST(VolumeReference, UniformSlabTransmittanceIsBeerLambert) {
  // Dark medium (no light, no ambient), white background: the centre pixel is exp(-sigma d).
  // Trilinear reconstruction ramps to 0 over one voxel past each face, which adds exactly one
  // voxel of thickness in all: d = nz * voxel.
  const int nz = 10;
  const double voxel = 0.5, density = 0.8;
  const DenseGrid g = uniform_slab(64, nz, float(density), voxel);
  VolumeMedium m;
  m.extinction = 0.3;
  m.light_color = glm::dvec3(0.0);
  m.ambient = glm::dvec3(0.0);
  m.background = glm::dvec3(1.0);
  const std::vector<float> light = light_optical_depth(g, m);
  const glm::vec3 c(16.0f, 16.0f, 0.0f);
  const CameraFrame cam = make_camera_frame(c + glm::vec3(0, 0, 40), c, {0, 1, 0}, 1.0f, 0.1f, 100.0f, 3, 3);
  const RgbImage img = render_volume_reference(g, light, cam, m, 0.25, 1);
  const double want = std::exp(-m.extinction * density * nz * voxel);
  EXPECT_NEAR(img.at(1, 1)[0], want, 1e-4);
}

DenseGrid gaussian_blob(int n) {
  DenseGrid g;
  g.dims = {n, n, n};
  g.values.resize(size_t(n) * n * n);
  const double c = 0.5 * (n - 1), s = 0.2 * n;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        g.values[(size_t(z) * n + y) * n + x] =
            float(std::exp(-((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c)) / (2 * s * s)));
  g.index_to_world = glm::dmat4(1.0);
  g.active_voxels = g.values.size();
  g.max_value = 1.0f;
  return g;
}

double max_abs_diff(const RgbImage& a, const RgbImage& b) {
  double m = 0.0;
  for (size_t i = 0; i < a.rgb.size(); ++i) m = std::max(m, double(std::abs(a.rgb[i] - b.rgb[i])));
  return m;
}

TEST(VolumeReference, RayMarchConvergesAsTheStepShrinks) {
  const DenseGrid g = gaussian_blob(24);
  VolumeMedium m;
  m.extinction = 0.25;
  const std::vector<float> light = light_optical_depth(g, m, 0.25);
  const CameraFrame cam = make_camera_frame({40, 30, 50}, {11.5f, 11.5f, 11.5f}, {0, 1, 0}, 40.0f, 0.1f, 200.0f, 24, 24);
  const RgbImage fine = render_volume_reference(g, light, cam, m, 0.0625, 2);
  double previous = 1e9;
  for (double step : {1.0, 0.5, 0.25}) {
    const double err = max_abs_diff(render_volume_reference(g, light, cam, m, step, 2), fine);
    EXPECT_LT(err, previous) << "step " << step;
    previous = err;
  }
  EXPECT_LT(previous, 2e-3);  // step 0.25 voxel: converged to the eye
}

TEST(VolumeReference, ImageDoesNotDependOnThreadCount) {
  const DenseGrid g = gaussian_blob(16);
  VolumeMedium m;
  m.extinction = 0.3;
  const std::vector<float> light = light_optical_depth(g, m);
  const CameraFrame cam = make_camera_frame({30, 20, 40}, {7.5f, 7.5f, 7.5f}, {0, 1, 0}, 40.0f, 0.1f, 200.0f, 17, 13);
  EXPECT_EQ(render_volume_reference(g, light, cam, m, 0.5, 1).rgb,
            render_volume_reference(g, light, cam, m, 0.5, 3).rgb);
}

TEST(LightSweep, AgreesWithTheMarchedOpticalDepthToTheLight) {
  const DenseGrid g = gaussian_blob(24);
  VolumeMedium m;
  m.extinction = 0.3;
  const std::vector<float> marched = light_optical_depth(g, m, 0.125);
  const std::vector<float> swept = light_optical_depth_sweep(g, m);
  // Where there is density, the one-pass propagation is within 10% (+0.02) of the march (its
  // bilinear resampling diffuses the shadow a little; measured worst about 7%).
  double worst = 0.0;
  for (size_t i = 0; i < g.values.size(); ++i)
    if (g.values[i] > 0.05f)
      worst = std::max(worst, std::abs(double(swept[i]) - marched[i]) / (0.02 + 0.10 * marched[i]));
  EXPECT_LE(worst, 1.0);
}

}  // namespace
}  // namespace pyro
