// VideoWriter and read_video: a small moving pattern through each codec and back (frame count,
// frame rate, PSNR at the default quality), and the failures that must leave nothing behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "engine/core/user_error.h"
#include "engine/io/io_error.h"
#include "engine/io/staging_folder.h"
#include "engine/io/video_file.h"
#include "engine/io/video_reader.h"
#include "tests/support/scratch_mount.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

constexpr int kVideoWidth = 64, kVideoHeight = 48, kVideoFrames = 12;

// Smooth gradients under a disc with a soft two-pixel edge that moves across the frame, RGB.
// The disc is a warm white, as a lit puff is: 4:2:0 video keeps a quarter of the chroma samples,
// and a saturated disc's sharp edge alone holds the PSNR near 35 dB even at CRF 0.
std::vector<uint8_t> video_test_frame(int width, int height, int index) {
  std::vector<uint8_t> rgb(static_cast<size_t>(width) * height * 3);
  const double cx = 10.0 + 3.5 * index, cy = 14.0 + 1.5 * index, radius = 9.0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double cover = std::clamp((radius + 0.5 - std::hypot(x - cx, y - cy)) / 2.0, 0.0, 1.0);
      const double base[3] = {40.0 + 160.0 * x / width, 60.0 + 120.0 * y / height,
                              110.0 + 50.0 * std::sin(0.08 * (x + y) + 0.3 * index)};
      const double disc[3] = {240.0, 225.0, 205.0};
      for (int c = 0; c < 3; ++c)
        rgb[(static_cast<size_t>(y) * width + x) * 3 + c] =
            static_cast<uint8_t>(std::lround(base[c] * (1.0 - cover) + disc[c] * cover));
    }
  return rgb;
}

// PSNR of `decoded` (decoded_width wide) against `expected` over expected's width * height.
double video_psnr(const std::vector<uint8_t>& expected, int width, int height,
                  const std::vector<uint8_t>& decoded, int decoded_width) {
  double squared = 0.0;
  for (int y = 0; y < height; ++y)
    for (int i = 0; i < width * 3; ++i) {
      const double d = double(expected[static_cast<size_t>(y) * width * 3 + i]) -
                       decoded[static_cast<size_t>(y) * decoded_width * 3 + i];
      squared += d * d;
    }
  const double mse = squared / (double(width) * height * 3);
  return mse == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

void write_test_video(const fs::path& path, int width, int height, int channels = 3) {
  VideoWriter writer(path.string(), width, height, 24.0);
  for (int i = 0; i < kVideoFrames; ++i) {
    std::vector<uint8_t> rgb = video_test_frame(width, height, i);
    if (channels == 4) {
      std::vector<uint8_t> rgba;
      for (size_t p = 0; p < rgb.size(); p += 3) rgba.insert(rgba.end(), {rgb[p], rgb[p + 1], rgb[p + 2], 7});
      rgb = std::move(rgba);
    }
    writer.add_frame(rgb.data(), channels);
  }
  writer.finish();
}

std::size_t video_folder_entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

void expect_video_round_trip(const std::string& name, int channels) {
  const fs::path dir = test::scratch_dir("video_" + name);
  const fs::path path = dir / ("clip." + name);
  write_test_video(path, kVideoWidth, kVideoHeight, channels);
  EXPECT_EQ(video_folder_entries(dir), 1u) << "the video and no temporary";
  const VideoClip clip = read_video(path.string());
  ASSERT_EQ(clip.frame_count(), kVideoFrames);
  EXPECT_EQ(clip.width, kVideoWidth);
  EXPECT_EQ(clip.height, kVideoHeight);
  EXPECT_NEAR(clip.fps, 24.0, 1e-9);
  double worst = 1e9;
  for (int i = 0; i < kVideoFrames; ++i) {
    const double psnr = video_psnr(video_test_frame(kVideoWidth, kVideoHeight, i), kVideoWidth,
                                   kVideoHeight, clip.frames[i], clip.width);
    EXPECT_GE(psnr, 35.0) << name << " frame " << i;
    worst = std::min(worst, psnr);
  }
  std::printf("%s at quality %d: worst frame PSNR %.2f dB, %lld bytes\n", name.c_str(),
              VideoWriter::default_quality, worst, static_cast<long long>(fs::file_size(path)));
}

TEST(VideoFile, Mp4KeepsFramesRateAndPsnr) { expect_video_round_trip("mp4", 3); }

TEST(VideoFile, WebmKeepsFramesRateAndPsnr) { expect_video_round_trip("webm", 4); }

TEST(VideoFile, GifKeepsFrameCountSizeAndColours) {
  const fs::path path = test::scratch_dir("video_gif") / "clip.gif";
  write_test_video(path, kVideoWidth, kVideoHeight);
  const VideoClip clip = read_video(path.string());
  ASSERT_EQ(clip.frame_count(), kVideoFrames);
  EXPECT_EQ(clip.width, kVideoWidth);
  EXPECT_EQ(clip.height, kVideoHeight);
  // One palette from every frame's pixels: the gradients and the disc within a few levels (a
  // fixed 3-3-2 palette, steps of 36 and 85 levels, errs by tens of levels without dithering).
  double sum = 0.0;
  for (int i = 0; i < kVideoFrames; ++i) {
    const std::vector<uint8_t> expected = video_test_frame(kVideoWidth, kVideoHeight, i);
    for (size_t k = 0; k < expected.size(); ++k) sum += std::abs(int(clip.frames[i][k]) - expected[k]);
  }
  const double mean = sum / (double(kVideoFrames) * kVideoWidth * kVideoHeight * 3);
  std::printf("gif: mean error %.3f levels of 255\n", mean);
  EXPECT_LE(mean, 6.0);
}

TEST(VideoFile, OddSizedMp4IsPaddedToEven) {
  const fs::path path = test::scratch_dir("video_odd") / "odd.mp4";
  write_test_video(path, 63, 47);
  const VideoClip clip = read_video(path.string());
  ASSERT_EQ(clip.frame_count(), kVideoFrames);
  EXPECT_EQ(clip.width, 64);
  EXPECT_EQ(clip.height, 48);
  EXPECT_GE(video_psnr(video_test_frame(63, 47, 5), 63, 47, clip.frames[5], clip.width), 35.0);
}

TEST(VideoFile, WithoutFinishNothingIsLeft) {
  const fs::path dir = test::scratch_dir("video_abandon");
  const fs::path path = dir / "clip.mp4";
  {
    VideoWriter writer(path.string(), kVideoWidth, kVideoHeight, 24.0);
    const std::vector<uint8_t> rgb = video_test_frame(kVideoWidth, kVideoHeight, 0);
    for (int i = 0; i < 3; ++i) writer.add_frame(rgb.data(), 3);
    const fs::path temporary = writer.temporary_path();
    EXPECT_EQ(temporary.parent_path(), dir);
    EXPECT_EQ(temporary.filename().string(), ".clip.mp4.partial-" + std::to_string(::getpid()));
    // The name remove_stale_staging recognizes once this process is gone.
    EXPECT_EQ(staging_owner(temporary.filename().string()), ::getpid());
    EXPECT_TRUE(fs::exists(temporary));
    EXPECT_FALSE(fs::exists(path));
  }
  EXPECT_EQ(video_folder_entries(dir), 0u);
}

TEST(VideoFile, DeadProcessTemporaryIsRemovedByTheNextWriter) {
  const fs::path dir = test::scratch_dir("video_stale");
  const fs::path stale = dir / ".clip.webm.partial-99999999";  // above any pid_max: gone
  std::ofstream(stale) << "cut by a kill";
  write_test_video(dir / "clip.webm", 16, 16);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_EQ(video_folder_entries(dir), 1u);
}

TEST(VideoFile, BadExtensionOrFolderIsTheUsersMistake) {
  const fs::path dir = test::scratch_dir("video_bad_name");
  try {
    VideoWriter writer((dir / "clip.avi").string(), 16, 16, 24.0);
    FAIL() << ".avi must be refused";
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("clip.avi"), std::string::npos) << what;
    for (const char* accepted : {".mp4", ".webm", ".gif"})
      EXPECT_NE(what.find(accepted), std::string::npos) << what;
  }
  EXPECT_THROW(VideoWriter((dir / "none" / "clip.mp4").string(), 16, 16, 24.0), UserError);
  EXPECT_THROW(read_video((dir / "none.mp4").string()), UserError);
  EXPECT_EQ(video_folder_entries(dir), 0u);
}

// A 64 KiB tmpfs with `free_blocks` pages of 4 KiB left free.
void fill_video_disk(const fs::path& dir, int free_blocks) {
  std::ofstream filler(dir / "filler", std::ios::binary);
  const std::vector<char> block(4096, 'x');
  for (int i = 0; i < 16 - free_blocks && filler.write(block.data(), block.size()); ++i) filler.flush();
}

void expect_no_space(const IoError& e) {
  EXPECT_NE(std::string(e.what()).find("clip.mp4"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
}

TEST(VideoFile, FullDiskThrowsIoErrorAndLeavesNoVideo) {
  const fs::path dir = test::scratch_dir("video_full_disk");
  test::ScratchMount disk(dir / "disk", "size=64k");
  if (!disk.mounted()) GTEST_SKIP() << disk.why();
  fill_video_disk(disk.dir(), 0);
  const fs::path path = disk.dir() / "clip.mp4";
  try {
    write_test_video(path, kVideoWidth, kVideoHeight);
    FAIL() << "a full disk must throw";
  } catch (const IoError& e) {
    expect_no_space(e);
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(video_folder_entries(disk.dir()), 1u) << "the filler alone: no temporary either";
}

TEST(VideoFile, DiskFillingUpMidVideoThrowsIoErrorAndLeavesNoVideo) {
  const fs::path dir = test::scratch_dir("video_fills_up");
  test::ScratchMount disk(dir / "disk", "size=64k");
  if (!disk.mounted()) GTEST_SKIP() << disk.why();
  fill_video_disk(disk.dir(), 2);
  const fs::path path = disk.dir() / "clip.mp4";
  int frames_before_error = -1;
  try {
    VideoWriter writer(path.string(), kVideoWidth, kVideoHeight, 24.0, 100);
    std::mt19937 rng(3);  // noise at CRF 0: about 9 KB a frame, more than the 8 KB left
    std::vector<uint8_t> noise(kVideoWidth * kVideoHeight * 3);
    for (frames_before_error = 0; frames_before_error < 40; ++frames_before_error) {
      for (uint8_t& v : noise) v = static_cast<uint8_t>(rng());
      writer.add_frame(noise.data(), 3);
    }
    writer.finish();
    FAIL() << "a full disk must throw";
  } catch (const IoError& e) {
    expect_no_space(e);
  }
  EXPECT_GT(frames_before_error, 0) << "the header fitted; a frame or the trailer found the disk full";
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(video_folder_entries(disk.dir()), 1u) << "the filler alone: no temporary either";
}

}  // namespace
}  // namespace pyro
