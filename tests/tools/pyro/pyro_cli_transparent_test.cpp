// pyro render --background transparent (scene key output.background "none"): frames over
// nothing, whose alpha is the coverage of the media and the meshes. Composited OVER the
// background the opaque frame shows, each transparent frame gives the opaque frame back: the
// EXR frames (premultiplied linear) to half-float precision, the PNG frames (straight alpha,
// composited in sRGB values) to one 8-bit level. Uncovered sky has alpha 0 and no colour, the
// meshes alpha 1, the media alpha between. Scenes with spherical-billboard media over meshes
// (explosion) and Gaussian splats over meshes (fog).
#include <gtest/gtest.h>

#include <ImfInputFile.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/io/exr_file.h"
#include "engine/io/png_file.h"
#include "engine/math/color.h"
#include "systems/runtime/scene/scene_loader.h"
#include "tests/support/cli_render.h"
#include "tests/support/file_bytes.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

constexpr int kTransparentSize = 48;

// Renders frame 2 of `scene` into dir/opaque and dir/transparent with `extra` options.
void render_both(const std::string& scene, const fs::path& dir, const std::vector<std::string>& extra) {
  const auto opaque = test::render(scene, dir / "opaque", "2:2", kTransparentSize, extra);
  ASSERT_EQ(opaque.exit_code, 0) << opaque.err;
  std::vector<std::string> transparent_extra = extra;
  transparent_extra.insert(transparent_extra.end(), {"--background", "transparent"});
  const auto transparent = test::render(scene, dir / "transparent", "2:2", kTransparentSize, transparent_extra);
  ASSERT_EQ(transparent.exit_code, 0) << transparent.err;
}

void expect_exr_over_background_is_opaque(const std::string& scene) {
  const fs::path dir = test::scratch_dir("transparent_exr_" + scene);
  render_both(scene, dir, {"--format", "exr", "--depth"});
  const fs::path t_path = dir / "transparent" / "frame_0002.exr";
  EXPECT_TRUE(Imf::InputFile(t_path.c_str()).isComplete());
  const ExrImage t = read_exr(t_path.string());
  const ExrImage o = read_exr((dir / "opaque" / "frame_0002.exr").string());
  ASSERT_EQ(t.rgba.size(), o.rgba.size());
  // The top-left corner sees sky alone: there the opaque frame holds the background.
  ASSERT_EQ(t.rgba[3], 0.0f) << "the sky is uncovered";
  const float background[3] = {o.rgba[0], o.rgba[1], o.rgba[2]};
  const glm::vec3 scene_background = load_scene(test::scene_path(scene)).background;
  for (int k = 0; k < 3; ++k)  // as the views hold it: at worst rounded to 8-bit sRGB
    EXPECT_NEAR(linear_to_srgb(background[k]), linear_to_srgb(scene_background[k]), 0.5 / 255.0);
  const double half_ulp = std::ldexp(1.0, -10);
  int partial = 0, mesh = 0;
  double worst = 0.0;
  for (size_t p = 0; p < t.depth.size(); ++p) {
    const float a = t.rgba[p * 4 + 3];
    EXPECT_GE(a, 0.0f);
    EXPECT_LE(a, 1.0f);
    partial += a > 0.01f && a < 0.99f;
    if (std::isfinite(t.depth[p])) {
      EXPECT_GE(a, 1.0f - half_ulp) << "a mesh covers pixel " << p;
      ++mesh;
    }
    for (int k = 0; k < 3; ++k) {
      const double over = t.rgba[p * 4 + k] + background[k] * (1.0 - a);
      const double want = o.rgba[p * 4 + k];
      worst = std::max(worst, std::abs(over - want) / (half_ulp * std::abs(want) + 1e-4));
    }
  }
  EXPECT_EQ(t.rgba[0], 0.0f) << "no colour where nothing covers the background";
  EXPECT_GT(partial, 0) << "the media's coverage lies between 0 and 1";
  EXPECT_GT(mesh, 0) << "the scene shows meshes";
  EXPECT_LE(worst, 1.0) << "largest error of the composite in units of 2^-10 relative + 1e-4";
}

TEST(PyroCliTransparent, ExrOverTheBackgroundIsTheOpaqueFrameWithMedia) {
  expect_exr_over_background_is_opaque("explosion.json");
}

TEST(PyroCliTransparent, ExrOverTheBackgroundIsTheOpaqueFrameWithSplats) {
  expect_exr_over_background_is_opaque("fog.json");
}

TEST(PyroCliTransparent, PngOverTheBackgroundIsTheOpaqueFrame) {
  const fs::path dir = test::scratch_dir("transparent_png");
  render_both("explosion.json", dir, {});
  const PngImage t = read_png((dir / "transparent" / "frame_0002.png").string());
  const PngImage o = read_png((dir / "opaque" / "frame_0002.png").string());
  ASSERT_EQ(t.channels, 4) << "RGBA";
  ASSERT_EQ(o.channels, 3);
  ASSERT_EQ(size_t(t.width) * t.height, size_t(o.width) * o.height);
  EXPECT_EQ(t.pixels[3], 0) << "the sky's corner is uncovered";
  int worst = 0, opaque_pixels = 0, partial = 0;
  for (size_t p = 0; p < size_t(t.width) * t.height; ++p) {
    const double a = t.pixels[p * 4 + 3] / 255.0;
    opaque_pixels += t.pixels[p * 4 + 3] == 255;
    partial += t.pixels[p * 4 + 3] > 0 && t.pixels[p * 4 + 3] < 255;
    for (int k = 0; k < 3; ++k) {
      // Straight alpha over the background byte the opaque frame shows in the sky.
      const double over = t.pixels[p * 4 + k] * a + o.pixels[k] * (1.0 - a);
      worst = std::max(worst, std::abs(int(std::lround(over)) - int(o.pixels[p * 3 + k])));
    }
  }
  EXPECT_LE(worst, 1) << "levels of 255";
  EXPECT_GT(opaque_pixels, 0) << "the ground is opaque";
  EXPECT_GT(partial, 0) << "the media are partly transparent";
}

TEST(PyroCliTransparent, TheSceneKeyGivesTheSameFramesAsTheOption) {
  const fs::path dir = test::scratch_dir("transparent_scene_key");
  std::string text = test::read_bytes(test::scene_path("explosion.json"));
  const std::string output = "\"output\": {";
  ASSERT_NE(text.find(output), std::string::npos);
  text.replace(text.find(output), output.size(), output + "\"background\": \"none\", ");
  std::ofstream(dir / "explosion.json") << text;
  const auto by_key = test::run_pyro({"render", (dir / "explosion.json").string(), "--out",
                                      (dir / "key").string(), "--frames", "1", "--width", "32",
                                      "--height", "32", "--format", "exr"});
  ASSERT_EQ(by_key.exit_code, 0) << by_key.err;
  const auto by_option = test::render("explosion.json", dir / "option", "1", 32,
                                      {"--format", "exr", "--background", "transparent"});
  ASSERT_EQ(by_option.exit_code, 0) << by_option.err;
  EXPECT_EQ(test::read_bytes(dir / "key" / "frame_0000.exr"),
            test::read_bytes(dir / "option" / "frame_0000.exr"));
}

TEST(PyroCliTransparent, AnUnknownBackgroundIsRefused) {
  const fs::path dir = test::scratch_dir("transparent_refused");
  const auto r = test::render("fog.json", dir / "out", "1", 16, {"--background", "clear"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--background"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace pyro
