// A scene whose `volumes[]` entry is a version 2 particle file: the world holds the particles as
// an AnisotropicCloud, placed as the entry says (centres moved and scaled, scales times the
// scale, extinction over it), and the frame shows them as the CPU reference does.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "components/anisotropic_cloud.h"
#include "components/frame_image.h"
#include "components/volume_source.h"
#include "engine/core/rng.h"
#include "engine/io/particle_file.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/reference/anisotropic_reference.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/random_anisotropic.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// The frame's RMSE against the reference of the placed particles; `render` is the scene's
// "render" object.
double scene_rmse(const std::string& render, const std::string& folder) {
  const fs::path dir = test::scratch_dir(folder);
  Rng rng(8);
  ParticleFile file;
  for (int i = 0; i < 20; ++i) file.anisotropic.push_back(test::random_anisotropic(rng, 0.5f, 0.03f, 0.15f, 2.0f, 8.0f));
  write_particle_file((dir / "cloud.pyrop").string(), file);
  const std::string scene_path = (dir / "scene.json").string();
  std::ofstream(scene_path) << R"({"output": {"width": 96, "height": 80}, "background": [0.2, 0.3, 0.5],
      "camera": {"position": [0.5, 0.4, 6], "target": [0.3, -0.2, 0], "fov_y_deg": 30, "near": 0.5},
      "render": )" + render + R"(,
      "volumes": [{"file": "cloud.pyrop", "anchor": "origin", "position": [0.3, -0.2, 0], "scale": 2}]})";
  const SceneDescription scene = load_scene(scene_path);
  // Placement by hand: p' = position + 2 p, scales doubled, extinction halved.
  std::vector<AnisotropicGaussian> placed = file.anisotropic;
  for (AnisotropicGaussian& g : placed) {
    g.centre = glm::vec3(0.3f, -0.2f, 0.0f) + 2.0f * g.centre;
    g.scale *= 2.0f;
    g.extinction /= 2.0f;
  }
  SceneRuntime runtime(scene);
  int clouds = 0;
  runtime.world().each<AnisotropicCloud, VolumeSource>([&](AnisotropicCloud& c, VolumeSource& src) {
    ++clouds;
    EXPECT_EQ(src.particles, 20u);
    ASSERT_EQ(c.particles.size(), placed.size());
    for (size_t i = 0; i < placed.size(); ++i) {
      EXPECT_NEAR(glm::length(c.particles[i].centre - placed[i].centre), 0.0f, 1e-6f);
      EXPECT_NEAR(glm::length(c.particles[i].scale - placed[i].scale), 0.0f, 1e-6f);
      EXPECT_NEAR(c.particles[i].extinction, placed[i].extinction, 1e-6f * placed[i].extinction);
    }
  });
  EXPECT_EQ(clouds, 1);
  runtime.step();
  const FrameImage& img = runtime.image();
  RgbImage gl;
  gl.width = img.width;
  gl.height = img.height;
  for (size_t i = 0; i < size_t(img.width) * img.height; ++i)
    for (int c = 0; c < 3; ++c) gl.rgb.push_back(img.rgba[4 * i + c]);
  const CameraDescription& cam = scene.camera;
  const CameraFrame frame = make_camera_frame(cam.position, cam.target, cam.up, cam.fov_y_deg, cam.near,
                                              cam.far, img.width, img.height);
  const RgbImage ref = render_anisotropic_reference(placed, frame, glm::dvec3(0.2, 0.3, 0.5));
  RgbImage bare = ref;
  for (size_t i = 0; i < bare.rgb.size(); ++i) bare.rgb[i] = i % 3 == 0 ? 0.2f : i % 3 == 1 ? 0.3f : 0.5f;
  const double rmse = image_rmse(gl, ref), signal = image_rmse(ref, bare);
  std::printf("anisotropic volume scene, render %s: rmse %.2e, signal %.3f\n", render.c_str(), rmse, signal);
  EXPECT_GT(signal, 0.05);
  return rmse;
}

TEST(AnisotropicVolumeScene, AVersionTwoFileIsPlacedAndDrawnAsTheReferenceShowsIt) {
  // Whole-particle compositing where particles overlap (the bar of tests/render/
  // anisotropic_splat_test.cpp) and the frame's half-float targets (relative 2^-11).
  EXPECT_LT(scene_rmse("{}", "anisotropic_volume"), 0.005);
}

TEST(AnisotropicVolumeScene, AHalfResolutionLayerHoldsThemToo) {
  // Drawn into the reduced-resolution particle layer and upsampled: the layer's resolution
  // blurs edges (a particle is a few layer pixels across), but nothing is lost or drawn twice
  // (either would cost about the whole signal, 0.1).
  EXPECT_LT(scene_rmse(R"({"layer_scale": 0.5})", "anisotropic_volume_layer"), 0.02);
}

}  // namespace
}  // namespace pyro
