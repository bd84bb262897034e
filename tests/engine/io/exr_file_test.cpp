// write_exr / read_exr: the round trip to half precision (colour) and exactly (depth), the
// channels OpenEXR itself reads from the header, and failures that leave nothing behind.
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <string>

#include "engine/core/user_error.h"
#include "engine/io/exr_file.h"
#include "engine/io/io_error.h"
#include "tests/support/scratch_mount.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// Values spread over the normal range of half floats (2^-14 .. 65504), with exact zeros.
ExrImage exr_test_image(int width, int height, bool with_depth) {
  ExrImage image{width, height, {}, {}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> log_value(-9.0f, 9.0f);
  for (int i = 0; i < width * height * 4; ++i)
    image.rgba.push_back(i % 11 == 0 ? 0.0f : std::exp(log_value(rng)));
  if (with_depth)
    for (int i = 0; i < width * height; ++i) image.depth.push_back(0.1f + 1e-3f * i + 1e-7f * (i % 7));
  return image;
}

std::size_t exr_folder_entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(ExrFile, RoundTripKeepsColourToHalfPrecisionAndDepthExactly) {
  const fs::path path = test::scratch_dir("exr_round_trip") / "frame.exr";
  const ExrImage in = exr_test_image(37, 23, true);
  write_exr(path.string(), in);
  const ExrImage out = read_exr(path.string());
  ASSERT_EQ(out.width, in.width);
  ASSERT_EQ(out.height, in.height);
  ASSERT_EQ(out.rgba.size(), in.rgba.size());
  // Rounding to the nearest half (11 significant bits) errs by at most 2^-11 of the value.
  const float half_relative = std::ldexp(1.0f, -11);
  for (size_t i = 0; i < in.rgba.size(); ++i)
    ASSERT_LE(std::fabs(out.rgba[i] - in.rgba[i]), half_relative * in.rgba[i]) << "value " << i;
  EXPECT_EQ(out.depth, in.depth) << "FLOAT depth is stored bit for bit";
}

TEST(ExrFile, HeaderHoldsHalfRgbaAndFloatZZipCompressed) {
  const fs::path dir = test::scratch_dir("exr_header");
  write_exr((dir / "depth.exr").string(), exr_test_image(8, 4, true));
  write_exr((dir / "plain.exr").string(), exr_test_image(8, 4, false));
  const auto channels_of = [](const fs::path& p) {
    Imf::InputFile file(p.c_str());
    EXPECT_EQ(file.header().compression(), Imf::ZIP_COMPRESSION);
    const Imath::Box2i window = file.header().dataWindow();
    EXPECT_EQ(window.max.x - window.min.x + 1, 8);
    EXPECT_EQ(window.max.y - window.min.y + 1, 4);
    std::map<std::string, Imf::PixelType> channels;
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
      channels[it.name()] = it.channel().type;
    return channels;
  };
  const std::map<std::string, Imf::PixelType> rgba = {
      {"R", Imf::HALF}, {"G", Imf::HALF}, {"B", Imf::HALF}, {"A", Imf::HALF}};
  auto with_z = rgba;
  with_z["Z"] = Imf::FLOAT;
  EXPECT_EQ(channels_of(dir / "depth.exr"), with_z);
  EXPECT_EQ(channels_of(dir / "plain.exr"), rgba);
  EXPECT_TRUE(read_exr((dir / "plain.exr").string()).depth.empty());
}

// OpenEXR writes a scan-line file's line-offset table (where each block of rows starts) when the
// OutputFile is closed; isComplete() checks that table against the file. A table left zeroed
// (bytes taken before the close) reads as incomplete, and readers must rebuild it by scanning.
TEST(ExrFile, WrittenFilesAreCompleteWithTheirLineOffsetTable) {
  const fs::path dir = test::scratch_dir("exr_complete");
  // 40 rows: three ZIP blocks of 16 rows, so the table has three entries.
  for (const bool with_depth : {false, true}) {
    const fs::path path = dir / (with_depth ? "depth.exr" : "plain.exr");
    write_exr(path.string(), exr_test_image(37, 40, with_depth));
    Imf::InputFile file(path.c_str());
    EXPECT_TRUE(file.isComplete()) << path;
  }
}

TEST(ExrFile, TopRowComesFirst) {
  const fs::path path = test::scratch_dir("exr_rows") / "rows.exr";
  ExrImage in{2, 3, std::vector<float>(2 * 3 * 4, 0.0f), {1.0f, 1.0f, 2.0f, 2.0f, 3.0f, 3.0f}};
  in.rgba[0] = 0.5f;  // red in the top-left pixel only
  write_exr(path.string(), in);
  Imf::InputFile file(path.c_str());
  std::vector<float> top_red(2), first_row_depth(2);
  Imf::FrameBuffer frame;
  const Imath::Box2i first_row(Imath::V2i(0, 0), Imath::V2i(1, 0));
  frame.insert("R", Imf::Slice::Make(Imf::FLOAT, top_red.data(), first_row));
  frame.insert("Z", Imf::Slice::Make(Imf::FLOAT, first_row_depth.data(), first_row));
  file.setFrameBuffer(frame);
  file.readPixels(0, 0);  // OpenEXR's y = 0 is the top row (INCREASING_Y)
  EXPECT_EQ(top_red[0], 0.5f);
  EXPECT_EQ(top_red[1], 0.0f);
  EXPECT_EQ(first_row_depth[0], 1.0f);
}

TEST(ExrFile, MissingFolderIsTheUsersMistake) {
  const fs::path path = test::scratch_dir("exr_missing") / "no_such_folder" / "frame.exr";
  EXPECT_THROW(write_exr(path.string(), exr_test_image(4, 4, false)), UserError);
  try {
    read_exr(path.string());
    FAIL() << "reading a missing file must throw";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

TEST(ExrFile, FullDiskThrowsIoErrorAndLeavesNoFile) {
  const fs::path dir = test::scratch_dir("exr_full_disk");
  test::ScratchMount disk(dir / "disk", "size=64k");
  if (!disk.mounted()) GTEST_SKIP() << disk.why();
  const fs::path path = disk.dir() / "frame.exr";
  // Noise does not deflate: about 190 KB of pixels for a 64 KB disk.
  try {
    write_exr(path.string(), exr_test_image(128, 128, true));
    FAIL() << "a full disk must throw";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("frame.exr"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(exr_folder_entries(disk.dir()), 0u) << "no temporary file either";
}

}  // namespace
}  // namespace pyro
