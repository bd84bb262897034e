// The EXR atlases of an atlas bake (atlas.exr, motion.exr): the linear colour is the PNG atlas
// before its highlight roll-off and 8-bit sRGB rounding, border fade included, and the exact
// motion is what motion.png holds before its 8-bit encoding, on the same axes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/core/content_path.h"
#include "engine/io/exr_file.h"
#include "engine/io/png_file.h"
#include "engine/math/color.h"
#include "systems/flipbook_fire/flipbook_atlas_sidecar.h"
#include "systems/flipbook_fire/flipbook_frame_fade.h"
#include "systems/flipbook_fire/flipbook_motion.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/open_scene/flipbook_bake.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace flipbook_linear_atlas_test {
namespace {

namespace fs = std::filesystem;

struct LinearAtlasBake {
  FlipbookBakeOptions options;
  AtlasSidecar sidecar;
  PngImage colour, motion;
  ExrImage linear, exact_motion;
};

LinearAtlasBake bake_linear_atlas() {
  LinearAtlasBake b;
  b.options.frames = 3;
  b.options.loop_blend = 0;
  b.options.width = 24;
  b.options.height = 36;
  b.options.atlas_columns = 2;
  b.options.atlas_rows = 2;
  const fs::path dir = test::scratch_dir("linear_atlas_bake");
  bake_flipbook(load_scene(test::scene_path("flipbook_fire.json")), b.options, dir.string());
  b.sidecar = parse_atlas_sidecar("atlas.json", nlohmann::json::parse(read_text_file((dir / "atlas.json").string())));
  b.colour = read_png((dir / b.sidecar.image).string());
  b.motion = read_png((dir / b.sidecar.motion_image).string());
  b.linear = read_exr((dir / b.sidecar.linear_image).string());
  b.exact_motion = read_exr((dir / b.sidecar.motion_linear_image).string());
  return b;
}

}  // namespace

TEST(FlipbookLinearAtlas, LinearColourIsThePngAtlasBeforeRollOffAndRounding) {
  const LinearAtlasBake b = bake_linear_atlas();
  ASSERT_EQ(b.sidecar.linear_image, "atlas.exr");
  const AtlasLayout& l = b.sidecar.layout;
  ASSERT_EQ(b.linear.width, l.width());
  ASSERT_EQ(b.linear.height, l.height());
  int compared = 0, lit = 0;
  for (int y = 0; y < l.height(); ++y)
    for (int x = 0; x < l.width(); ++x) {
      if ((y / l.frame_height) * l.columns + x / l.frame_width >= b.sidecar.frames) continue;
      const size_t i = static_cast<size_t>(y) * l.width() + x;
      const float k = frame_fade_weight(b.options.fade, l.frame_width, l.frame_height, x % l.frame_width,
                                        y % l.frame_height);
      const float* c = &b.linear.rgba[i * 4];
      // Where the unfaded colour is within 1 the roll-off leaves it alone: there the PNG is the
      // EXR rounded to 8-bit sRGB.
      if (k > 0.0f && std::max({c[0], c[1], c[2]}) > k) continue;
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(srgb_to_linear(b.colour.pixels[i * 3 + ch] / 255.0f), c[ch], 6e-3f)
            << "pixel " << x << ", " << y << " channel " << ch;
      ++compared;
      lit += c[0] > 0.05f;
    }
  EXPECT_GT(compared, l.frame_width * l.frame_height);
  EXPECT_GT(lit, 20);
}

TEST(FlipbookLinearAtlas, ExactMotionIsTheEncodedMotionUnrounded) {
  const LinearAtlasBake b = bake_linear_atlas();
  ASSERT_EQ(b.sidecar.motion_linear_image, "motion.exr");
  const AtlasLayout& l = b.sidecar.layout;
  const MotionField png = decode_motion(b.motion.pixels, l.width(), l.height(), b.sidecar.motion_strength);
  ASSERT_EQ(b.exact_motion.width, l.width());
  double moving = 0.0;
  for (size_t i = 0; i < png.uv.size() / 2; ++i) {
    const int x = static_cast<int>(i % static_cast<size_t>(l.width())), y = static_cast<int>(i / static_cast<size_t>(l.width()));
    if ((y / l.frame_height) * l.columns + x / l.frame_width >= b.sidecar.frames) continue;  // an unused tile
    // motion.png's G is v up, decoded here to v down; motion.exr's G is v up. The PNG rounds to
    // half a step of 2 strength / 255; the EXR's half floats to half a unit in the last of 10 bits.
    const float u = b.exact_motion.rgba[i * 4 + 0], v_up = b.exact_motion.rgba[i * 4 + 1];
    const float png_step = b.sidecar.motion_strength / 255.0f + 1e-6f;
    EXPECT_NEAR(u, png.uv[i * 2], png_step + std::fabs(u) / 2048.0f);
    EXPECT_NEAR(v_up, -png.uv[i * 2 + 1], png_step + std::fabs(v_up) / 2048.0f);
    moving += std::fabs(b.exact_motion.rgba[i * 4 + 1]);
  }
  EXPECT_GT(moving, 0.0);
}

}  // namespace flipbook_linear_atlas_test
}  // namespace pyro
