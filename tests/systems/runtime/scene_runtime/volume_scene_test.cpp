// Scenes with volumes: an OpenVDB file imported on load and a particle file render through the
// sorting and billboard systems; placement; a bad grid is a user error naming the scene, the
// entry and the volume file, with nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "components/frame_image.h"
#include "components/particle_set.h"
#include "components/volume_source.h"
#include "engine/io/particle_file.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/cloud_import/scene_volume.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/density_ball.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// A soft ball of density, 20^3 voxels of 0.1 world units centred near the origin.
void write_ball(const std::string& path) { test::write_density_ball(path, 20, 9.0, 0.1, -0.95); }

std::string scene_text(const std::string& volume) {
  return R"({"output": {"width": 64, "height": 64}, "background": [0.2, 0.3, 0.5],
            "camera": {"position": [0, 0, 6], "target": [0, 0, 0], "fov_y_deg": 30},
            "light": {"direction": [0, -1, 0], "color": [1, 1, 1], "ambient": [0.2, 0.2, 0.2]},
            "volumes": [)" + volume + "]}";
}

std::string write_scene(const fs::path& dir, const std::string& volume) {
  const std::string path = (dir / "scene.json").string();
  std::ofstream(path) << scene_text(volume);
  return path;
}

float luminance_volume_scene(const FrameImage& img, int x, int y) {
  const float* p = &img.rgba[4 * (size_t(y) * img.width + x)];
  return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

TEST(VolumeScene, AVdbVolumeRendersLitFromAbove) {
  const fs::path dir = test::scratch_dir("vdb");
  write_ball((dir / "ball.vdb").string());
  const SceneDescription scene = load_scene(write_scene(dir, R"({"file": "ball.vdb"})"));
  SceneRuntime runtime(scene);
  size_t volumes = 0, particles = 0;
  runtime.world().each<VolumeSource, ParticleSet>([&](VolumeSource& src, ParticleSet& set) {
    ++volumes;
    particles = set.pool.size();
    EXPECT_EQ(src.particles, set.pool.size());
    EXPECT_GT(src.active_voxels, 0u);
  });
  EXPECT_EQ(volumes, 1u);
  EXPECT_GT(particles, 0u);
  runtime.step();
  const FrameImage& img = runtime.image();
  // The corner shows the sky, the centre shows the cloud.
  EXPECT_NEAR(img.rgba[0], 0.2f, 2e-3f);
  EXPECT_NEAR(img.rgba[2], 0.5f, 2e-3f);
  const float* c = &img.rgba[4 * (size_t(32) * 64 + 32)];
  EXPECT_GT(c[0] - 0.2f, 0.1f);  // a white cloud over a blue sky: far more red
  // Lit from above (top row first): the upper part of the ball is brighter than the lower part.
  EXPECT_GT(luminance_volume_scene(img, 32, 25), luminance_volume_scene(img, 32, 39) + 0.05f);
}

TEST(VolumeScene, AParticleFileRendersLikeTheVdbItCameFrom) {
  const fs::path dir = test::scratch_dir("pyrop");
  write_ball((dir / "ball.vdb").string());
  const SceneDescription from_vdb =
      load_scene(write_scene(dir, R"({"file": "ball.vdb", "anchor": "origin"})"));
  ParticleFile pf;
  pf.particles = load_scene_volume(from_vdb, from_vdb.volumes[0]).particles;
  write_particle_file((dir / "ball.pyrop").string(), pf);
  const SceneDescription from_pyrop =
      load_scene(write_scene(dir, R"({"file": "ball.pyrop", "anchor": "origin"})"));

  SceneRuntime a(from_vdb), b(from_pyrop);
  a.step();
  b.step();
  const FrameImage& ia = a.image();
  const FrameImage& ib = b.image();
  ASSERT_EQ(ia.rgba.size(), ib.rgba.size());
  double worst = 0.0;
  for (size_t i = 0; i < ia.rgba.size(); ++i) worst = std::max(worst, double(std::abs(ia.rgba[i] - ib.rgba[i])));
  EXPECT_LT(worst, 1e-6);
}

TEST(VolumeScene, PlacementMovesAndScalesAndKeepsTheLook) {
  std::vector<GaussianParticle> ps = {{1, 1, 1, 0.5f, 0.5f, 1, 1, 1}, {3, 1, 1, 0.5f, 0.5f, 1, 1, 1}};
  VolumeDescription v;
  v.position = {10, 0, 0};
  v.size = 4.0f;  // longest side of the centres' box is 2: scale 2
  place_volume_particles(ps, v);
  EXPECT_FLOAT_EQ(ps[0].x, 8.0f);
  EXPECT_FLOAT_EQ(ps[1].x, 12.0f);
  EXPECT_FLOAT_EQ(ps[0].y, 0.0f);
  EXPECT_FLOAT_EQ(ps[0].radius, 1.0f);
  EXPECT_FLOAT_EQ(ps[0].density, 0.5f);  // a change of units: the look is kept
  VolumeDescription o;
  o.anchor_center = false;
  o.scale = 0.5f;
  place_volume_particles(ps, o);
  EXPECT_FLOAT_EQ(ps[1].x, 6.0f);
  EXPECT_FLOAT_EQ(ps[1].density, 0.5f);
}

TEST(VolumeScene, ABadGridIsAUserErrorAndNothingIsWritten) {
  const fs::path dir = test::scratch_dir("badgrid");
  write_ball((dir / "ball.vdb").string());
  const std::string scene = write_scene(dir, R"({"file": "ball.vdb", "grid": "temperature"})");
  const fs::path out = dir / "out";
  const test::CommandResult r = test::run_pyro({"render", scene, "--out", out.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(scene + ": at /volumes/0/file"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find((dir / "ball.vdb").string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("temperature"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(VolumeScene, TheFallbackIsSaidAloud) {
  const fs::path dir = test::scratch_dir("fallback");
  write_ball((dir / "ball.vdb").string());
  const std::string scene = write_scene(dir, R"({"file": "absent.vdb", "fallback": "ball.vdb"})");
  const test::CommandResult r =
      test::run_pyro({"render", scene, "--out", (dir / "out").string(), "--width", "32", "--height", "32"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("not found; using the fallback"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "frame_0000.png"));
}

}  // namespace
}  // namespace pyro
