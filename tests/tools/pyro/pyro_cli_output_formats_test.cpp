// pyro render's output sinks end to end: EXR frames hold the linear framebuffer (to half-float
// precision) with alpha, and with --depth the view depth of the geometry (against the ground
// plane's closed form); a video decodes to the PNG frames within the codec's error, with the
// frame count and fps asked for, in mono and left-right stereo; a full disk and a kill leave no
// half-written EXR frame or video.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include <ImfInputFile.h>
#include <glm/glm.hpp>

#include "components/frame_image.h"
#include "engine/io/exr_file.h"
#include "engine/io/png_file.h"
#include "engine/io/video_reader.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/cli_render.h"
#include "tests/support/scratch_mount.h"
#include "tests/support/spawn_pyro.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

constexpr int kExrWidth = 48, kExrHeight = 32;

// Frame 1 of fog.json at the EXR test's size, read back linear in this process.
FrameImage linear_fog_frame_one() {
  RuntimeOptions o;
  o.width_override = kExrWidth;
  o.height_override = kExrHeight;
  SceneRuntime runtime(load_scene(test::scene_path("fog.json")), o);
  runtime.draw_frame(1);
  return runtime.image();
}

// The view depth at which the ray through pixel (x, y)'s centre meets the ground plane y = 0
// (a ray-plane intersection: the closed form the depth channel must give).
float ground_depth(const CameraFrame& cam, int x, int y) {
  const glm::mat4 inverse = glm::inverse(cam.view_projection);
  const float nx = (x + 0.5f) / cam.width * 2.0f - 1.0f, ny = 1.0f - (y + 0.5f) / cam.height * 2.0f;
  const glm::vec4 a = inverse * glm::vec4(nx, ny, -1.0f, 1.0f), b = inverse * glm::vec4(nx, ny, 1.0f, 1.0f);
  const glm::vec3 p0 = glm::vec3(a) / a.w, dir = glm::vec3(b) / b.w - p0;
  const float t = -p0.y / dir.y;
  return view_depth(cam, p0 + t * dir);
}

TEST(PyroCliExr, FramesAreTheLinearFramebufferWithAlphaAndTheGroundsDepth) {
  const fs::path out = test::scratch_dir("exr_frames") / "out";
  const auto r = test::run_pyro({"render", test::scene_path("fog.json"), "--out", out.string(),
                                 "--frames", "2", "--width", std::to_string(kExrWidth), "--height",
                                 std::to_string(kExrHeight), "--format", "exr", "--depth"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(fs::exists(out / "frame_0000.exr"));
  const ExrImage exr = read_exr((out / "frame_0001.exr").string());
  const FrameImage truth = linear_fog_frame_one();
  ASSERT_EQ(exr.width, truth.width);
  ASSERT_EQ(exr.height, truth.height);
  ASSERT_EQ(exr.rgba.size(), truth.rgba.size());
  double worst = 0.0;
  for (size_t i = 0; i < exr.rgba.size(); ++i) {
    // Half floats keep 11 significant bits: a relative error of at most 2^-11.
    const double bound = std::abs(truth.rgba[i]) * std::ldexp(1.0, -11) + 1e-7;
    worst = std::max(worst, std::abs(exr.rgba[i] - truth.rgba[i]) / bound);
  }
  EXPECT_LE(worst, 1.0) << "largest error in units of half-float precision";

  const SceneDescription scene = load_scene(test::scene_path("fog.json"));
  const CameraDescription& c = scene.camera;
  const CameraFrame cam = make_camera_frame(c.position, c.target, c.up, c.fov_y_deg,
                                            c.near, c.far, kExrWidth, kExrHeight);
  ASSERT_EQ(exr.depth.size(), size_t(kExrWidth) * kExrHeight) << "a Z channel";
  for (int y = kExrHeight - 3; y < kExrHeight; ++y)  // the bottom rows see the ground
    for (int x = 0; x < kExrWidth; x += 7)
      EXPECT_NEAR(exr.depth[size_t(y) * kExrWidth + x], ground_depth(cam, x, y),
                  1e-3 * ground_depth(cam, x, y)) << x << ", " << y;
  EXPECT_EQ(exr.depth[0], std::numeric_limits<float>::infinity()) << "the sky: no geometry";
}

TEST(PyroCliExr, FramesAreCompleteOpenExrFiles) {
  const fs::path out = test::scratch_dir("exr_complete_frames") / "out";
  const auto r = test::render("fog.json", out, "2", 40, {"--format", "exr", "--depth"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : {"frame_0000.exr", "frame_0001.exr"}) {
    Imf::InputFile file((out / name).c_str());
    EXPECT_TRUE(file.isComplete()) << name << ": the line-offset table is written";
  }
}

TEST(PyroCliExr, StereoWritesAFilePerEyeAndDepthNeedsExr) {
  const fs::path dir = test::scratch_dir("exr_stereo");
  const auto r = test::render("fog.json", dir / "out", "1", 24, {"--format", "exr", "--stereo", "left-right"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "frame_0000_left.exr"));
  EXPECT_TRUE(fs::exists(dir / "out" / "frame_0000_right.exr"));
  EXPECT_TRUE(read_exr((dir / "out" / "frame_0000_left.exr").string()).depth.empty());
  const auto refused = test::render("fog.json", dir / "png", "1", 24, {"--depth"});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--format exr"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir / "png"));
}

// Peak signal-to-noise ratio of an RGB8 frame against a PNG's RGB pixels, in dB.
double psnr_against_png(const std::vector<uint8_t>& rgb, const PngImage& png, int x0, int width) {
  double sum = 0.0;
  for (int y = 0; y < png.height; ++y)
    for (int x = 0; x < png.width; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        const double d = double(rgb[(size_t(y) * width + x0 + x) * 3 + ch]) -
                         png.pixels[(size_t(y) * png.width + x) * png.channels + ch];
        sum += d * d;
      }
  const double mse = sum / (double(png.width) * png.height * 3);
  return mse == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

TEST(PyroCliVideo, DecodesToThePngFramesWithTheFrameCountAndFps) {
  const fs::path dir = test::scratch_dir("video_frames");
  const fs::path video = dir / "explosion.mp4";
  const auto r = test::render("explosion.json", dir / "out", "12", 64, {"--video", video.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const VideoClip clip = read_video(video.string());
  EXPECT_EQ(clip.frame_count(), 12);
  EXPECT_NEAR(clip.fps, load_scene(test::scene_path("explosion.json")).frames_per_second, 1e-6);
  double worst = 99.0;
  for (int f = 0; f < clip.frame_count(); ++f) {
    const PngImage png = read_png((dir / "out" / ("frame_00" + std::string(f < 10 ? "0" : "") +
                                                  std::to_string(f) + ".png")).string());
    ASSERT_EQ(clip.width, png.width);
    worst = std::min(worst, psnr_against_png(clip.frames[f], png, 0, clip.width));
  }
  std::printf("mp4 at the default quality: worst frame %.2f dB against the PNG frames\n", worst);
  EXPECT_GE(worst, 35.0);
}

// The mean and the largest absolute difference, in 8-bit levels over every channel of every
// frame, between a GIF's frames and the PNG frames of the same render.
struct GifError {
  double mean = 0.0;
  int max = 0;
};

GifError gif_error_against_pngs(const VideoClip& clip, const fs::path& frames) {
  GifError e;
  double sum = 0.0;
  size_t n = 0;
  for (int f = 0; f < clip.frame_count(); ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", f);
    const PngImage png = read_png((frames / name).string());
    EXPECT_EQ(png.width, clip.width);
    EXPECT_EQ(png.height, clip.height);
    for (size_t p = 0; p < size_t(png.width) * png.height; ++p)
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(int(clip.frames[f][p * 3 + c]) - png.pixels[p * png.channels + c]);
        sum += d;
        e.max = std::max(e.max, d);
        ++n;
      }
  }
  e.mean = n ? sum / double(n) : 0.0;
  return e;
}

TEST(PyroCliVideo, GifFramesAreWithinEightLevelsOfThePngFrames) {
  const fs::path dir = test::scratch_dir("video_gif_error");
  const fs::path video = dir / "explosion.gif";
  const auto r = test::render("explosion.json", dir / "out", "12", 64, {"--video", video.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const VideoClip clip = read_video(video.string());
  ASSERT_EQ(clip.frame_count(), 12);
  const GifError e = gif_error_against_pngs(clip, dir / "out");
  std::printf("gif against the PNG frames: mean %.2f, max %d levels of 255\n", e.mean, e.max);
  EXPECT_LE(e.mean, 8.0);
}

TEST(PyroCliVideo, LeftRightStereoIsEncodedSideBySide) {
  const fs::path dir = test::scratch_dir("video_stereo");
  const fs::path video = dir / "fog.webm";
  const auto r = test::render("fog.json", dir / "out", "3", 32,
                              {"--stereo", "left-right", "--video", video.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const VideoClip clip = read_video(video.string());
  ASSERT_EQ(clip.frame_count(), 3);
  ASSERT_EQ(clip.width, 64);
  for (const auto& [eye, x0] : {std::pair<const char*, int>{"left", 0}, {"right", 32}}) {
    const PngImage png = read_png((dir / "out" / ("frame_0002_" + std::string(eye) + ".png")).string());
    EXPECT_GE(psnr_against_png(clip.frames[2], png, x0, clip.width), 35.0) << eye;
  }
}

TEST(PyroCliVideo, AFullDiskLeavesNoVideoAndTheFolderAsItWas) {
  const fs::path dir = test::scratch_dir("video_full_disk");
  test::ScratchMount disk(dir / "disk", "size=8k");
  if (!disk.mounted()) GTEST_SKIP() << disk.why();
  const fs::path video = disk.dir() / "fog.mp4";
  const auto r = test::render("explosion.json", dir / "out", "40", 128,
                              {"--video", video.string(), "--video-quality", "100"});
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("fog.mp4"), std::string::npos) << "names the file: " << r.err;
  EXPECT_TRUE(fs::is_empty(disk.dir())) << "no video and no temporary";
  EXPECT_FALSE(fs::exists(dir / "out")) << "the frames are not moved in without the video";
}

TEST(PyroCliExr, AFullDiskKeepsTheEarlierFramesAndLeavesNothingPartial) {
  const fs::path dir = test::scratch_dir("exr_full_disk");
  test::ScratchMount disk(dir / "disk", "size=200k");
  if (!disk.mounted()) GTEST_SKIP() << disk.why();
  const fs::path out = disk.dir() / "out";
  ASSERT_EQ(test::render("fog.json", out, "0:1", 64, {"--format", "exr"}).exit_code, 0);
  const auto before = test::contents(out);
  const auto r = test::render("fog.json", out, "60", 64, {"--format", "exr"});
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(".exr"), std::string::npos) << "names the file: " << r.err;
  EXPECT_EQ(test::contents(out), before) << "the earlier frames, byte for byte, and nothing else";
}

bool staging_holds_exr(const fs::path& out) {
  std::error_code ec;
  for (fs::directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().rfind(".partial-", 0) == 0)
      for (fs::directory_iterator f(it->path(), ec); !ec && f != end; f.increment(ec))
        if (f->path().extension() == ".exr") return true;
  return false;
}

// SIGKILL mid-render (no unwinding): no video at its path; the resumed run keeps the finished
// EXR frames, writes the video whole and removes the killed run's temporary.
TEST(PyroCliVideo, AKilledRenderLeavesNoVideoAndResumesToTheSameFrames) {
  const fs::path dir = test::scratch_dir("video_kill");
  const fs::path out = dir / "out", video = dir / "fog.webm";
  const std::vector<std::string> extra = {"--format", "exr", "--video", video.string()};
  const pid_t pid = test::spawn_pyro(test::render_args("fog.json", out, "30", 48, extra));
  for (int i = 0; i < 1200 && !staging_holds_exr(out); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  ASSERT_TRUE(staging_holds_exr(out)) << "the render never finished a frame";
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  EXPECT_FALSE(fs::exists(video)) << "nothing under the video's name";

  std::vector<std::string> resume = extra;
  resume.push_back("--resume");
  const auto r = test::render("fog.json", out, "30", 48, resume);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_video(video.string()).frame_count(), 30);
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << e.path();
  const fs::path whole = dir / "whole";
  ASSERT_EQ(test::render("fog.json", whole, "30", 48, {"--format", "exr"}).exit_code, 0);
  for (const char* f : {"frame_0000.exr", "frame_0029.exr"})
    EXPECT_EQ(test::read_bytes(out / f), test::read_bytes(whole / f)) << f;
}

}  // namespace
}  // namespace pyro
