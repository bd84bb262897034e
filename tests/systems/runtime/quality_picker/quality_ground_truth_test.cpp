// The pieces the quality picker stands on: the depth-to-distance inversion against the forward
// perspective map, the reference over an opaque scene at its limits (nothing in front of the
// surface: the surface; no surface: the plain reference), and the candidate list.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/math/camera_math.h"
#include "components/frame_image.h"
#include "components/gpu_frame.h"
#include "components/particle_set.h"
#include "components/view.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/quality_picker/quality_measurement.h"
#include "systems/runtime/quality_picker/quality_picker.h"
#include "systems/runtime/reference/particle_reference.h"
#include "systems/runtime/reference/pixel_ray.h"
#include "tests/support/test_paths.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "systems/runtime/reference/world_snapshot.h"

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

// Half the particles are under the ground, which hides them from the GL render; the truth must
// cut them at the ground's depth too, or the bright particles would show over the dark ground.
// Measured: GL vs the cut truth 0.013, the uncut image vs the cut truth 0.105.
TEST(QualityGroundTruth, CpuTruthAgreesWithTheGlRenderWhereTheGroundHidesParticles) {
  const SceneDescription scene = parse_scene(
      R"({"name": "half buried", "seed": 3, "output": {"width": 64, "height": 48},
          "background": [0.5, 0.55, 0.6],
          "camera": {"position": [0, 4, 8], "target": [0, 0, 0], "fov_y_deg": 45},
          "clouds": [{"count": 80, "radius": 0.5, "density": 0.5, "color": 0.95,
                      "box": {"min": [-2, -2, -2], "max": [2, 1, 2]}}],
          "meshes": [{"type": "ground_plane", "scale": 20, "color": [0.2, 0.2, 0.2]}]})",
      "half_buried.json");
  const QualityGroundTruth truth(scene, 64, 48, {0});
  ASSERT_TRUE(truth.cpu_reference());
  const double rmse = measure_rmse(scene, 64, 48, full_resolution_defaults(scene), truth);
  EXPECT_LT(rmse, 0.02);

  // Control: the same particles over the same opaque image but not cut at its depth are far from
  // the GL render, so the agreement above rests on the cut.
  SceneDescription opaque = scene;
  opaque.clouds.clear();
  RuntimeOptions o;
  o.width_override = 64;
  o.height_override = 48;
  SceneRuntime background(opaque, o), particles(scene, o);
  background.step();
  particles.step();
  const CameraFrame camera = particles.world().resource<View>().eyes.at(0);
  const ParticlePool all = gather_particles(particles.world());
  RgbImage behind;
  behind.width = 64;
  behind.height = 48;
  for (size_t i = 0; i < background.image().rgba.size(); ++i)
    if (i % 4 != 3) behind.rgb.push_back(background.image().rgba[i]);
  const std::vector<float> stop = ray_stop_distances(
      camera, background.world().resource<GpuFrame>().eyes.at(0).scene->read_depth());
  const RgbImage cut = render_particles_reference_over(all, camera, behind, stop);
  const RgbImage uncut = render_particles_reference_over(
      all, camera, behind, std::vector<float>(stop.size(), std::numeric_limits<float>::infinity()));
  EXPECT_EQ(cut.rgb, truth.image(0).rgb);  // what QualityGroundTruth builds, rebuilt here
  EXPECT_GT(image_rmse(uncut, truth.image(0)), 3.0 * rmse);
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

// Thick clouds (centre opacity at least 1 - 1/e) also try the 128-texel map; thinner ones do not.
TEST(QualityCandidates, ThickCloudsAlsoTryTheFinerMap) {
  SceneDescription lit;
  lit.render.particles = ParticleShape::gaussian;
  lit.shadows = ShadowSettings{};
  lit.clouds.emplace_back();
  lit.clouds.back().density = 0.62f;
  const auto finer = [](const std::vector<QualitySettings>& c) {
    return std::count_if(c.begin(), c.end(), [](const QualitySettings& q) {
      return q.shadows && q.shadows->method == ShadowMethod::shadow_map && q.shadows->map_size == 128 &&
             q.shadows->map_slices == 64;
    });
  };
  EXPECT_EQ(finer(quality_candidates(lit)), 0);
  lit.clouds.back().density = 0.7f;
  EXPECT_EQ(finer(quality_candidates(lit)), 12);  // layer scales x footprints
}

TEST(QualityCandidates, LitScenesAlsoChooseTheirShadows) {
  SceneDescription lit;
  lit.render.particles = ParticleShape::gaussian;
  lit.shadows = ShadowSettings{};
  lit.shadows->map_size = 96;  // the scene's own setting is a candidate too
  const auto c = quality_candidates(lit);
  EXPECT_EQ(c.size(), 4u * 3u * 5u);  // layer scales x footprints x (none, map 32, map 64, rays, own)
  int rays = 0, none = 0, own = 0;
  for (const QualitySettings& q : c) {
    ASSERT_TRUE(q.shadows.has_value());
    rays += q.shadows->method == ShadowMethod::rays;
    none += q.shadows->method == ShadowMethod::none;
    own += q.shadows->map_size == 96;
  }
  EXPECT_EQ(rays, 12);
  EXPECT_EQ(none, 12);
  EXPECT_EQ(own, 12);
  const QualitySettings d = full_resolution_defaults(lit);
  ASSERT_TRUE(d.shadows.has_value());
  EXPECT_EQ(d.shadows->map_size, 96);
  EXPECT_NE(std::find(c.begin(), c.end(), d), c.end());
  // Applied, the choice replaces the scene's method and map, and survives the cache's JSON.
  QualitySettings q = c.back();
  q.shadows = ShadowChoice{ShadowMethod::rays, 32, 16};
  const SceneDescription t = apply_quality_settings(lit, q);
  EXPECT_EQ(t.shadows->method, ShadowMethod::rays);
  EXPECT_EQ(t.shadows->map_slices, 16);
  EXPECT_EQ(quality_settings_from_json(to_json(q)), q);
  // An unlit scene keeps none.
  EXPECT_FALSE(apply_quality_settings(SceneDescription{}, q).shadows.has_value());
}

// clouds.json lit: the pick measures every shadow method against the reference with exact
// shadows, picks one that meets the target, and says which; lit without shadows never does.
TEST(QualityPick, ALitSceneGetsAShadowMethodThatMeetsTheTarget) {
  SceneDescription scene = load_scene(test::scene_path("clouds.json"));
  scene.shadows = ShadowSettings{};
  QualitySearch search;
  search.frames = {0};
  search.timed_frames = 1;
  const QualityPick pick = pick_quality(scene, 80, 60, 0.03, "test", false, search, nullptr);
  ASSERT_TRUE(pick.met);
  ASSERT_TRUE(pick.settings.shadows.has_value());
  EXPECT_NE(pick.settings.shadows->method, ShadowMethod::none);
  EXPECT_LE(pick.expected_rmse, 0.85 * 0.03);
  for (const nlohmann::json& c : pick.candidates)
    if (c["settings"]["shadows"]["method"] == "none") {
      EXPECT_FALSE(c["qualifies"].get<bool>()) << c.dump();
    }
  EXPECT_NE(quality_pick_note(pick, scene).find(", shadows "), std::string::npos) << quality_pick_note(pick, scene);
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
