// The campfire keeps black-body hues: `pyro render content/scenes/campfire.json --stereo
// side-by-side` at frames 5 and 19 has at most 0.5% of its coloured pixels yellow-green (hue
// 58°-100°, saturation > 0.25, value > 0.15; tests/support/pixel_hue.h), a colour black-body
// emission never makes. Clipping each channel at the display's 1, where the baked flame's hot
// core and the overlapped billboards exceed it, made about 5% of them so (olive where dimmed);
// the final pass now rolls highlights off without a hue shift (engine/math/highlight_rolloff.h).
#include <gtest/gtest.h>

#include <string>

#include "engine/io/png_file.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/open_scene/flipbook_bake.h"
#include "tests/support/pixel_hue.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(CampfireTint, OverlappedFlamesKeepBlackBodyHuesInBothEyes) {
  const auto dir = test::scratch_dir("campfire_tint");
  const auto r = test::run_pyro({"render", test::scene_path("campfire.json"), "--stereo", "side-by-side",
                                 "--frames", "5:19", "--out", dir.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* frame : {"frame_0005.png", "frame_0019.png"}) {
    const PngImage image = read_png((dir / frame).string());
    const test::HueCensus census = test::hue_census(image.pixels, image.channels);
    const size_t pixels = size_t(image.width) * size_t(image.height);
    // The fire covers a good part of the frame: the census is not of a handful of pixels.
    EXPECT_GT(census.coloured, pixels / 20) << frame;
    EXPECT_LE(census.fraction(), 0.005) << frame << ": " << census.yellow_green << " of "
                                        << census.coloured << " coloured pixels are yellow-green";
  }
}

// Where the tint came from: the baked flame's hot core exceeds the display's range, and clipped
// per channel it turned saturated yellow, which a dimmed billboard then shows as olive. Baked
// twenty times overexposed, the flame's frames still keep black-body hues (they read white at the
// core instead); with per-channel clipping a quarter of their coloured pixels are yellow-green.
TEST(CampfireTint, AnOverexposedBakeKeepsBlackBodyHues) {
  SceneDescription scene = load_scene(test::scene_path("flipbook_fire.json"));
  scene.render.fire_emission *= 20.0f;
  FlipbookBakeOptions options;
  options.frames = 4;
  options.loop_blend = 0;
  options.width = 96;
  options.height = 144;
  const auto dir = test::scratch_dir("campfire_tint_overexposed_bake");
  bake_flipbook(scene, options, dir.string());
  test::HueCensus census;
  size_t saturated = 0;  // pixels with a channel at the display's limit
  for (int f = 0; f < options.frames; ++f) {
    const PngImage image = read_png((dir / ("frame_000" + std::to_string(f) + ".png")).string());
    const test::HueCensus one = test::hue_census(image.pixels, image.channels);
    census.coloured += one.coloured;
    census.yellow_green += one.yellow_green;
    for (size_t i = 0; i + 2 < image.pixels.size(); i += size_t(image.channels))
      saturated += image.pixels[i] == 255 || image.pixels[i + 1] == 255 || image.pixels[i + 2] == 255;
  }
  EXPECT_GT(saturated, 100u);  // overexposed indeed
  EXPECT_GT(census.coloured, 1000u);
  EXPECT_LE(census.fraction(), 0.005) << census.yellow_green << " of " << census.coloured;
}

}  // namespace
}  // namespace pyro
