// Flipbooks from a folder of PNG frames ("flames from anywhere"): frames read in order,
// RGB frames made transparent where black, the thesis' preparation steps (crop, black base line,
// softened base) against their closed form, and bad folders refused naming the folder or file,
// also through `pyro render` (exit 2, nothing written).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "engine/core/user_error.h"
#include "systems/flipbook_fire/flipbook_folder.h"
#include "engine/io/png_file.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

void write_frame(const fs::path& file, int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  std::vector<uint8_t> px(static_cast<size_t>(w) * h * 3);
  for (size_t i = 0; i < px.size(); i += 3) {
    px[i] = r;
    px[i + 1] = g;
    px[i + 2] = b;
  }
  write_png(file.string(), w, h, 3, px);
}

void write_frames(const fs::path& dir, int count, int w, int h) {
  fs::create_directories(dir);
  for (int f = 0; f < count; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", f);
    write_frame(dir / name, w, h, static_cast<uint8_t>(10 * f), 40, 0);
  }
}

template <class F>
std::string user_error_of(F&& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

TEST(FlipbookFolder, ReadsFramesInNumberOrderWithAlphaFromBrightness) {
  const fs::path dir = test::scratch_dir("frames");
  for (int f : {0, 1, 2, 9, 10, 11, 3, 4, 5, 6, 7, 8}) {  // frame_9 before frame_10 though unpadded
    write_frame(dir / ("frame_" + std::to_string(f) + ".png"), 4, 6, static_cast<uint8_t>(20 * f), 5, 0);
  }
  const FlipbookFrames frames = read_flipbook_folder(dir.string());
  ASSERT_EQ(frames.rgba.size(), 12u);
  EXPECT_EQ(frames.width, 4);
  EXPECT_EQ(frames.height, 6);
  for (int f = 0; f < 12; ++f) {
    EXPECT_EQ(frames.rgba[static_cast<size_t>(f)][0], 20 * f) << f;
    EXPECT_EQ(frames.rgba[static_cast<size_t>(f)][3], std::max(20 * f, 5)) << "alpha = brightest channel";
  }
}

TEST(FlipbookFolder, RefusesGapsSizesEmptyFoldersAndManifestMismatch) {
  const fs::path dir = test::scratch_dir("bad");
  EXPECT_NE(user_error_of([&] { read_flipbook_folder((dir / "absent").string()); }).find("absent"),
            std::string::npos);
  EXPECT_NE(user_error_of([&] { read_flipbook_folder(dir.string()); }).find("found none"), std::string::npos);
  write_frames(dir, 5, 8, 12);
  fs::remove(dir / "frame_0002.png");
  const std::string gap = user_error_of([&] { read_flipbook_folder(dir.string()); });
  EXPECT_NE(gap.find(dir.string()), std::string::npos) << gap;
  EXPECT_NE(gap.find("none numbered 2 between frame_0001.png and frame_0003.png"), std::string::npos) << gap;
  write_frame(dir / "frame_0002.png", 8, 10, 1, 2, 3);
  const std::string size = user_error_of([&] { read_flipbook_folder(dir.string()); });
  EXPECT_NE(size.find("frame_0002.png"), std::string::npos) << size;
  EXPECT_NE(size.find("expected a frame of 8x12 pixels"), std::string::npos) << size;
  write_frame(dir / "frame_0002.png", 8, 12, 1, 2, 3);
  EXPECT_NO_THROW(read_flipbook_folder(dir.string()));
  std::ofstream(dir / "flipbook.json") << "{\"frames\": 6}";
  const std::string count = user_error_of([&] { read_flipbook_folder(dir.string()); });
  EXPECT_NE(count.find("expected 6 frames in the folder, found 5"), std::string::npos) << count;
  std::ofstream(dir / "flipbook.json") << "{\"frames\": 5}";
  EXPECT_NO_THROW(read_flipbook_folder(dir.string()));
  std::ofstream(dir / "frame_0003.png") << "not a png";
  const std::string bad = user_error_of([&] { read_flipbook_folder(dir.string()); });
  EXPECT_NE(bad.find("frame_0003.png"), std::string::npos) << bad;
}

TEST(FlipbookFolder, PreparationCropsAndSoftensTheBase) {
  const fs::path dir = test::scratch_dir("prep");
  write_frames(dir, 1, 40, 100);
  FlipbookFrames frames = read_flipbook_folder(dir.string());
  const uint8_t green = frames.rgba[0][1];
  ASSERT_EQ(green, 40);
  FlipbookPreparation p;
  p.crop = {0.25f, 0.0f, 0.75f, 0.8f};  // 20 x 80 pixels from the top
  p.base_line = 0.1f;
  p.soften = 0.25f;
  prepare_flipbook(frames, p);
  ASSERT_EQ(frames.width, 20);
  ASSERT_EQ(frames.height, 80);
  for (int y = 0; y < 80; ++y) {
    const float a = (80 - y - 0.5f) / 80.0f;  // height above the bottom
    const float keep = a < 0.1f ? 0.0f : a < 0.35f ? (a - 0.1f) / 0.25f : 1.0f;
    for (int x : {0, 19})
      EXPECT_EQ(frames.rgba[0][(static_cast<size_t>(y) * 20 + x) * 4 + 1], std::lround(40 * keep)) << "row " << y;
  }
}

TEST(FlipbookFolder, RenderRefusesABadFlipbookWithExit2AndWritesNothing) {
  const fs::path dir = test::scratch_dir("cli");
  write_frames(dir / "flames", 3, 8, 12);
  write_frame(dir / "flames" / "frame_0001.png", 9, 12, 1, 1, 1);
  std::ofstream(dir / "scene.json")
      << R"({"output": {"width": 32, "height": 24}, "fires": [{"flipbook": "flames"}]})";
  const fs::path out = dir / "out";
  const test::CommandResult r =
      test::run_pyro({"render", (dir / "scene.json").string(), "--out", out.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("frame_0001.png"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // A flipbook folder that does not exist: the scene's JSON pointer is named.
  std::ofstream(dir / "scene.json")
      << R"({"output": {"width": 32, "height": 24}, "fires": [{"flipbook": "nowhere"}]})";
  const test::CommandResult missing =
      test::run_pyro({"render", (dir / "scene.json").string(), "--out", out.string()});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("/fires/0/flipbook"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace pyro
