// cloud_fitted.json (a version 2 particle file: anisotropic Gaussians fitted at import) lit by its
// sun every frame, with its forward lobe and octaves, against the CPU reference with exact shadows through the ellipsoids
// (render_lit_anisotropic_reference_over, through particle_scene_references): both shadow methods within the bar (whole-frame RMSE 0.02),
// lit without shadows not; the sun turned between two frames of one runtime relights the cloud
// without loading it again.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "components/anisotropic_cloud.h"
#include "components/directional_light.h"
#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "systems/runtime/quality_picker/quality_measurement.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/rendered_frame.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

constexpr int kLitFittedCloudWidth = 160, kLitFittedCloudHeight = 90;

// The shipped scene (lit, with a forward lobe and three octaves) with `method`.
SceneDescription lit_fitted(ShadowMethod method) {
  SceneDescription scene = load_scene(test::scene_path("cloud_fitted.json"));
  EXPECT_TRUE(scene.shadows.has_value());
  scene.shadows.emplace(scene.shadows.value_or(ShadowSettings{})).method = method;
  return scene;
}

SceneRuntime runtime_of(const SceneDescription& scene) {
  return test::readback_runtime(scene, kLitFittedCloudWidth, kLitFittedCloudHeight);
}

RgbImage reference_of(const SceneDescription& scene) {
  return particle_scene_references(scene, kLitFittedCloudWidth, kLitFittedCloudHeight, {0}).at(0);
}

double rmse(ShadowMethod method, const RgbImage& reference) {
  SceneRuntime runtime = runtime_of(lit_fitted(method));
  runtime.draw_frame(0);
  const double e = image_rmse(rgb_of(runtime.image()), reference);
  std::printf("%s: rmse %.5f\n", name_of(method).data(), e);
  return e;
}

class LitFittedCloud : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    reference_ = new RgbImage(reference_of(lit_fitted(ShadowMethod::rays)));
  }
  static void TearDownTestSuite() { delete reference_; }
  static RgbImage* reference_;
};
RgbImage* LitFittedCloud::reference_ = nullptr;

TEST_F(LitFittedCloud, TheParticlesCarryTheImportsAlbedo) {
  SceneRuntime runtime = runtime_of(lit_fitted(ShadowMethod::rays));
  const ParticleFile file = read_particle_file(content_path("volumes/sample_cloud_fitted.pyrop"));
  const float albedo = float(imported_albedo("sample_cloud_fitted.pyrop", file));
  int clouds = 0;
  runtime.world().each<const AnisotropicCloud>([&](const AnisotropicCloud& c) {
    ++clouds;
    ASSERT_EQ(c.particles.size(), file.anisotropic.size());
    for (const AnisotropicGaussian& g : c.particles) EXPECT_EQ(g.color, glm::vec3(albedo));
  });
  EXPECT_EQ(clouds, 1);
}

TEST_F(LitFittedCloud, ExactShadowRaysAreWithinTheBar) { EXPECT_LE(rmse(ShadowMethod::rays, *reference_), 0.02); }

TEST_F(LitFittedCloud, TheOpacityShadowMapIsWithinTheBar) {
  EXPECT_LE(rmse(ShadowMethod::shadow_map, *reference_), 0.02);
}

TEST_F(LitFittedCloud, WithoutShadowsTheFrameIsNot) { EXPECT_GT(rmse(ShadowMethod::none, *reference_), 0.04); }

TEST(LitFittedCloudRelight, ASunTurnedBetweenFramesRelightsTheSameParticles) {
  SceneDescription scene = lit_fitted(ShadowMethod::shadow_map);
  SceneRuntime runtime = runtime_of(scene);
  runtime.draw_frame(0);
  const RgbImage first = rgb_of(runtime.image());
  const glm::vec3 turned_sun(-0.7f, -0.3f, -0.6f);
  runtime.world().each<DirectionalLight>([&](DirectionalLight& l) { l.direction = turned_sun; });
  runtime.draw_frame(1);
  const RgbImage turned = rgb_of(runtime.image());
  for (DirectionalLight& l : scene.directional_lights) l.direction = turned_sun;
  const double moved = image_rmse(first, turned), error = image_rmse(turned, reference_of(scene));
  std::printf("relit from a new sun: rmse %.5f against its reference; the frame moved by %.5f\n", error, moved);
  EXPECT_LE(error, 0.02);
  EXPECT_GT(moved, 2.0 * error);
}

// One flat particle facing the eye, the sun along its breadth: the view ray crosses little of it
// (alpha about 0.3), the sunlight much (an optical depth of about 3 from one edge to the other),
// so the light falls across the face as the particle's own closed-form depth toward the sun says,
// averaged through the particle's thickness. Without that term (the others' depth is zero here)
// the face is evenly lit (RMSE 0.06).
TEST(LitFittedParticle, AFlatParticleShadowsItselfAcrossItsFace) {
  const std::filesystem::path dir = test::scratch_dir("lit_fitted_particle");
  ParticleFile file;
  AnisotropicGaussian g;
  g.scale = {1.0f, 0.6f, 0.05f};
  g.extinction = 4.0f;
  g.color = glm::vec3(0.9f);
  file.anisotropic.push_back(g);
  write_particle_file((dir / "flat.pyrop").string(), file);
  const std::string path = (dir / "scene.json").string();
  std::ofstream(path) << R"({"output": {"width": 96, "height": 64}, "background": [0.1, 0.1, 0.1],
      "camera": {"position": [0, 0, 8], "target": [0, 0, 0], "fov_y_deg": 40, "near": 0.5},
      "lights": [{"type": "directional", "direction": [-1, -0.1, 0], "color": [1, 1, 1]},
                 {"type": "ambient", "color": [0.1, 0.1, 0.1]}],
      "shadows": {"method": "rays"},
      "volumes": [{"file": "flat.pyrop", "anchor": "origin", "scale": 1}]})";
  const SceneDescription scene = load_scene(path);
  SceneRuntime runtime(scene, [] {
    RuntimeOptions o;
    o.readback = true;
    return o;
  }());
  runtime.draw_frame(0);
  const RgbImage engine = rgb_of(runtime.image());
  const RgbImage reference = particle_scene_references(scene, 96, 64, {0}).at(0);
  // The reference's fall-off across the face: the sunward edge against the far one.
  const float near_edge = reference.at(62, 32)[0], far_edge = reference.at(34, 32)[0];
  const double e = image_rmse(engine, reference);
  std::printf("flat particle: rmse %.5f; reference %.3f at the sunward edge, %.3f at the far one\n", e, near_edge,
              far_edge);
  EXPECT_GT(near_edge, 1.5f * far_edge);
  // Shaded at the densest point of each pixel's ray alone, 0.0083 (the core's depth for all of
  // it); averaged over the density, 0.0015.
  EXPECT_LE(e, 0.004);
}

// The reference traces one kind of Gaussian: a scene with isotropic and fitted particles is
// refused by name rather than measured against a truth that leaves some of them out.
TEST(LitFittedParticle, TheReferenceRefusesAMixOfBothKinds) {
  const std::filesystem::path dir = test::scratch_dir("lit_mixed_particles");
  ParticleFile fitted, isotropic;
  AnisotropicGaussian g;
  g.extinction = 2.0f;
  fitted.anisotropic.push_back(g);
  isotropic.particles.push_back(GaussianParticle{0.5f, 0.0f, 0.0f, 0.3f, 0.4f, 0.8f, 0.8f, 0.8f});
  write_particle_file((dir / "fitted.pyrop").string(), fitted);
  write_particle_file((dir / "isotropic.pyrop").string(), isotropic);
  const std::string path = (dir / "mixed.json").string();
  std::ofstream(path) << R"({"output": {"width": 32, "height": 24}, "shadows": {},
      "volumes": [{"file": "fitted.pyrop", "anchor": "origin"}, {"file": "isotropic.pyrop", "anchor": "origin"}]})";
  try {
    particle_scene_references(load_scene(path), 32, 24, {0});
    ADD_FAILURE() << "a mix of both kinds was measured";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("mixed.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("found both"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pyro
