// Motion blur by blending frames (Umenhoffer et al. 2006, section 4; scene key
// render.motion_blur = b): each output is (1 - b) times the new frame plus b times the previous
// output, in linear light. Checked on the explosion's first frames (which change fast) against
// the same frames rendered without blur, through the sRGB PNGs the engine writes; and
// `pyro render --frames A:B` of a blurred scene equals frames A..B of a full run.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/io/png_file.h"
#include "systems/output/png_sink.h"
#include "systems/runtime/scene/scene_loader.h"
#include "engine/math/color.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/small_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> output_png(SceneRuntime& run, const fs::path& dir, int f) {
  const std::vector<std::string> files =
      write_shown_png(run.read_shown(), (dir / ("f" + std::to_string(f))).string(), false);
  return read_png(files.at(0)).pixels;
}

TEST(MotionBlur, EachOutputBlendsTheNewFrameWithThePreviousOutputInLinearLight) {
  SceneDescription scene = load_scene(test::scene_path("explosion.json"));
  SceneRuntime plain(scene, test::small_runtime());
  const float b = 0.6f;
  scene.render.motion_blur = b;
  SceneRuntime blurred(scene, test::small_runtime());
  const fs::path dir = test::scratch_dir("motion_blur");
  std::vector<uint8_t> previous;
  double largest_change = 0.0, worst = 0.0, worst_srgb_blend = 0.0;
  for (int f = 0; f < 6; ++f) {
    plain.step();
    blurred.step();
    const std::vector<uint8_t> a = output_png(plain, dir, 2 * f), out = output_png(blurred, dir, 2 * f + 1);
    ASSERT_EQ(a.size(), out.size());
    if (f == 0) {
      // Nothing to blend with: the same image, but for the half-float history's rounding.
      for (size_t i = 0; i < a.size(); ++i) ASSERT_LE(std::abs(int(a[i]) - int(out[i])), 1) << i;
    } else {
      for (size_t i = 0; i < a.size(); ++i) {
        const double lin_new = srgb_to_linear(a[i] / 255.0), lin_prev = srgb_to_linear(previous[i] / 255.0);
        const double expected = linear_to_srgb((1.0 - b) * lin_new + b * lin_prev) * 255.0;
        worst = std::max(worst, std::abs(out[i] - expected));
        // What blending the encoded values would give: a different image where frames differ.
        worst_srgb_blend = std::max(worst_srgb_blend, std::abs((1.0 - b) * a[i] + b * previous[i] - expected));
        largest_change = std::max(largest_change, std::abs(double(a[i]) - previous[i]));
      }
    }
    previous = out;
  }
  EXPECT_GT(largest_change, 30.0) << "the frames change, so blending shows";
  // The history is kept in half floats, the expectation rebuilt from 8-bit PNGs.
  std::printf("worst %.3f levels; blending sRGB values would be off by %.3f\n", worst, worst_srgb_blend);
  EXPECT_LE(worst, 1.5);
  EXPECT_GT(worst_srgb_blend, 2.5) << "the test tells linear from sRGB blending";
}

TEST(MotionBlur, ARangeOfFramesEqualsTheSameFramesOfAFullRun) {
  nlohmann::json scene;
  std::ifstream(test::scene_path("explosion.json")) >> scene;
  scene["render"]["motion_blur"] = 0.5;
  const fs::path dir = test::scratch_dir("motion_blur_range");
  const fs::path file = dir / "blurred.json";
  std::ofstream(file) << scene.dump();
  const auto full = test::run_pyro({"render", file.string(), "--out", (dir / "full").string(),
                                    "--width", "48", "--height", "48", "--frames", "5"});
  ASSERT_EQ(full.exit_code, 0) << full.err;
  const auto part = test::run_pyro({"render", file.string(), "--out", (dir / "part").string(),
                                    "--width", "48", "--height", "48", "--frames", "3:4"});
  ASSERT_EQ(part.exit_code, 0) << part.err;
  for (const char* name : {"frame_0003.png", "frame_0004.png"})
    EXPECT_EQ(read_png((dir / "full" / name).string()).pixels,
              read_png((dir / "part" / name).string()).pixels)
        << name;
}

TEST(MotionBlur, AnOutOfRangeWeightIsRefused) {
  const fs::path dir = test::scratch_dir("motion_blur_bad");
  nlohmann::json scene;
  std::ifstream(test::scene_path("explosion.json")) >> scene;
  scene["render"]["motion_blur"] = 1.0;
  const fs::path file = dir / "bad.json";
  std::ofstream(file) << scene.dump();
  const auto bad = test::run_pyro({"render", file.string(), "--out", (dir / "out").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("/render/motion_blur"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace pyro
