// The pieces the quality picker stands on: the depth-to-distance inversion against the forward
// perspective map, the reference over an opaque scene at its limits (nothing in front of the
// surface: the surface; no surface: the plain reference), and the candidate list.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/math/camera_math.h"
#include "systems/quality/quality_picker.h"
#include "systems/reference/particle_reference.h"
#include "systems/reference/pixel_ray.h"

namespace pyro {
namespace {

CameraFrame small_camera() {
  return make_camera_frame({0.0f, 1.0f, 6.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 50.0f, 0.1f,
                           100.0f, 24, 18);
}

TEST(QualityGroundTruth, RayStopDistancesInvertThePerspectiveDepth) {
  const CameraFrame c = small_camera();
  const double n = c.near, f = c.far;
  std::vector<float> depth(size_t(c.width) * c.height);
  std::vector<double> z(depth.size());
  for (size_t i = 0; i < depth.size(); ++i) {
    z[i] = 0.5 + 0.37 * double(i);  // view depths from 0.5 to ~160 (some beyond far)
    if (z[i] >= f) z[i] = f * 0.999;
    // glm::perspective: z_ndc = (f + n) / (f - n) - 2 f n / ((f - n) z); window d = (z_ndc + 1) / 2.
    const double z_ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * z[i]);
    depth[i] = float(0.5 * (z_ndc + 1.0));
  }
  depth[3] = 1.0f;  // the far plane: nothing there
  const std::vector<float> t = ray_stop_distances(c, depth);
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      const size_t i = size_t(y) * c.width + x;
      if (i == 3) {
        EXPECT_TRUE(std::isinf(t[i]));
        continue;
      }
      const glm::dvec3 w = pixel_ray_direction(c, x + 0.5, y + 0.5);
      const double expected = z[i] / glm::dot(w, glm::dvec3(c.forward));
      // A float d has ulp <= 6e-8 near 1 and dd/dz = f n / ((f - n) z^2) ~ 0.1 / z^2 here, so z
      // carries up to ~6e-7 z^2 from the rounding of d alone.
      EXPECT_NEAR(t[i], expected, 1e-6 * expected * expected + 1e-5 * expected) << i;
    }
}

ParticlePool three_particles() {
  ParticlePool p(3);
  for (int k = 0; k < 3; ++k) {
    ParticleInit init;
    init.position = {-0.6f + 0.6f * float(k), 1.0f, -0.3f * float(k)};
    init.radius = 0.9f;
    init.density = 0.5f;
    init.color = {0.9f, 0.5f + 0.1f * float(k), 0.2f};
    p.spawn(init);
  }
  return p;
}

TEST(QualityGroundTruth, ReferenceOverASurfaceAtItsLimits) {
  const CameraFrame c = small_camera();
  const ParticlePool p = three_particles();
  const glm::dvec3 sky(0.25, 0.375, 0.625);  // exact in float, as `behind` stores it
  RgbImage behind;
  behind.width = c.width;
  behind.height = c.height;
  behind.rgb.assign(size_t(3) * c.width * c.height, 0.0f);
  for (size_t i = 0; i < behind.rgb.size(); ++i) behind.rgb[i] = float(sky[int(i % 3)]);
  const size_t pixels = size_t(c.width) * c.height;

  // No surface: the plain reference over the sky, exactly.
  const std::vector<float> none(pixels, std::numeric_limits<float>::infinity());
  const RgbImage plain = render_particles_reference(p, c, sky, 1);
  const RgbImage over = render_particles_reference_over(p, c, behind, none, 1);
  EXPECT_EQ(over.rgb, plain.rgb);
  EXPECT_GT(image_rmse(plain, behind), 0.01);  // the particles are in view

  // A surface at the eye: nothing in front of it, the image is the surface.
  RgbImage wall = behind;
  for (size_t i = 0; i < wall.rgb.size(); ++i) wall.rgb[i] = float(i % 7) / 7.0f;
  const RgbImage blocked = render_particles_reference_over(p, c, wall, std::vector<float>(pixels, 0.0f), 1);
  EXPECT_EQ(blocked.rgb, wall.rgb);
}

TEST(QualityCandidates, SearchTheKnobsEachSceneHas) {
  SceneDescription gaussian;
  gaussian.render.particles = ParticleShape::gaussian;
  EXPECT_EQ(quality_candidates(gaussian).size(), 4u * 3u);  // layer scales x footprint sizes
  SceneDescription explosion;
  explosion.render.particles = ParticleShape::spherical;
  explosion.render.shading = ParticleShading::explosion;
  explosion.emitters.emplace_back();
  const auto c = quality_candidates(explosion);
  EXPECT_EQ(c.size(), 4u * 2u);  // layer scales x substeps
  for (const QualitySettings& q : c) EXPECT_EQ(q.footprint_size, explosion.footprint.size);
  const QualitySettings d = full_resolution_defaults(explosion);
  EXPECT_EQ(d.layer_scale, 1.0f);
  EXPECT_EQ(d.substeps, 1);
}

TEST(QualitySettings, ApplyingSubstepsMultipliesTheFrameRate) {
  SceneDescription s;
  s.frames_per_second = 24.0f;
  const SceneDescription t = apply_quality_settings(s, {0.25f, 32, 3});
  EXPECT_EQ(t.frames_per_second, 72.0f);
  EXPECT_EQ(t.render.layer_scale, 0.25f);
  EXPECT_EQ(t.footprint.size, 32);
}

}  // namespace
}  // namespace pyro
