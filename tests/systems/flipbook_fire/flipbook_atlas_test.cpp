// Flipbook atlases and motion vectors: the tile order (tile (c, r) is frame r columns + c), the
// sidecar's refusals naming atlas.json and the key, an atlas folder read into the same frames as
// a folder of those frames, the motion-vector encoding of particles moving uniformly decoding to
// their projected motion (closed form, within 8-bit quantization), the motion-vector blend of a
// translated pattern beating the linear blend, and a small atlas bake of the fire scene.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include <glm/trigonometric.hpp>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/png_file.h"
#include "systems/flipbook_fire/flipbook_atlas.h"
#include "systems/flipbook_fire/flipbook_atlas_sidecar.h"
#include "systems/flipbook_fire/flipbook_folder.h"
#include "systems/flipbook_fire/flipbook_motion_blend.h"
#include "systems/flipbook_fire/particle_motion_splat.h"
#include "systems/runtime/scene/scene_loader.h"
#include "components/gpu_frame.h"
#include "systems/runtime/open_scene/flipbook_bake.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// Frame f of a made-up flipbook: every byte a function of (frame, pixel, channel).
std::vector<uint8_t> atlas_test_frame(int f, int w, int h) {
  std::vector<uint8_t> px(static_cast<size_t>(w) * h * 3);
  for (size_t i = 0; i < px.size(); ++i) px[i] = static_cast<uint8_t>(37 * f + 3 * i + 1);
  return px;
}

TEST(FlipbookAtlas, TileAtColumnAndRowHoldsFrameRowTimesColumnsPlusColumn) {
  const AtlasLayout layout{3, 2, 4, 5};
  std::vector<std::vector<uint8_t>> frames;
  for (int f = 0; f < 5; ++f) frames.push_back(atlas_test_frame(f, 4, 5));
  const std::vector<uint8_t> atlas = pack_atlas(layout, frames, 3);
  ASSERT_EQ(atlas.size(), size_t(12 * 10 * 3));
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c)
      for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 4; ++x)
          for (int ch = 0; ch < 3; ++ch) {
            const uint8_t got = atlas[((size_t(r) * 5 + y) * 12 + size_t(c) * 4 + x) * 3 + ch];
            const int f = r * 3 + c;
            const uint8_t want = f < 5 ? frames[size_t(f)][(size_t(y) * 4 + x) * 3 + ch] : 0;
            ASSERT_EQ(got, want) << "tile " << c << "," << r;
          }
  EXPECT_EQ(split_atlas(layout, atlas, 3, 5), frames);
  EXPECT_THROW(parse_atlas_grid("8", "--atlas"), UserError);
  EXPECT_THROW(parse_atlas_grid("0x4", "--atlas"), UserError);
  EXPECT_EQ(parse_atlas_grid("8x4", "--atlas").rows, 4);
}

// An atlas folder of `frames` 4x5 frames on a 3x2 grid; `edit` changes the sidecar's JSON.
fs::path write_test_atlas(const std::string& name, int frames,
                          const std::function<void(nlohmann::json&)>& edit = {}) {
  const fs::path dir = test::scratch_dir(name);
  AtlasSidecar s;
  s.layout = {3, 2, 4, 5};
  s.frames = frames;
  std::vector<std::vector<uint8_t>> colour;
  for (int f = 0; f < frames; ++f) colour.push_back(atlas_test_frame(f, 4, 5));
  write_png((dir / "atlas.png").string(), 12, 10, 3, pack_atlas(s.layout, colour, 3));
  nlohmann::json j = atlas_sidecar_json(s);
  if (edit) edit(j);
  std::ofstream((dir / "atlas.json").string()) << j.dump(2);
  return dir;
}

void expect_sidecar_refusal(const fs::path& dir, const std::string& place) {
  try {
    read_flipbook_folder(dir.string());
    ADD_FAILURE() << "no error for " << place;
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), (dir / "atlas.json").string());
    EXPECT_EQ(e.place(), place) << e.what();
  }
}

TEST(FlipbookAtlas, AnAtlasFolderReadsAsTheFolderOfItsFrames) {
  const fs::path atlas = write_test_atlas("atlas_reads_as_folder", 5);
  const fs::path folder = test::scratch_dir("atlas_reads_as_folder_frames");
  for (int f = 0; f < 5; ++f)
    write_png((folder / ("frame_000" + std::to_string(f) + ".png")).string(), 4, 5, 3, atlas_test_frame(f, 4, 5));
  const FlipbookFrames a = read_flipbook_folder(atlas.string());
  const FlipbookFrames b = read_flipbook_folder(folder.string());
  EXPECT_EQ(a.width, 4);
  EXPECT_EQ(a.height, 5);
  EXPECT_EQ(a.rgba, b.rgba);
  EXPECT_TRUE(a.motion.empty());
}

TEST(FlipbookAtlas, BadSidecarsAreRefusedNamingTheFileAndTheKey) {
  expect_sidecar_refusal(write_test_atlas("atlas_no_columns", 5, [](nlohmann::json& j) { j.erase("columns"); }),
                         "/columns");
  expect_sidecar_refusal(write_test_atlas("atlas_wrong_width", 5, [](nlohmann::json& j) { j["frame_width"] = 5; }),
                         "/image");
  expect_sidecar_refusal(write_test_atlas("atlas_too_many", 5, [](nlohmann::json& j) { j["frames"] = 7; }),
                         "/frames");
  expect_sidecar_refusal(write_test_atlas("atlas_linear", 5, [](nlohmann::json& j) { j["color_space"] = "linear"; }),
                         "/color_space");
  expect_sidecar_refusal(
      write_test_atlas("atlas_bad_strength", 5,
                       [](nlohmann::json& j) { j["motion_vectors"] = {{"image", "motion.png"}, {"strength", -1}}; }),
      "/motion_vectors/strength");
}

TEST(FlipbookMotion, UniformlyMovingParticlesDecodeToTheirProjectedMotion) {
  const int w = 40, h = 60;
  const float fov = 30.0f, depth = 2.0f, dt = 1.0f / 30.0f;
  const CameraFrame camera = make_camera_frame({0, 0, depth}, {0, 0, 0}, {0, 1, 0}, fov, 0.1f, 10.0f, w, h);
  const glm::vec3 velocity(0.6f, -0.9f, 0.0f);  // parallel to the image plane: the same motion everywhere
  std::vector<MotionParticle> particles;
  for (int i = 0; i < 25; ++i)
    particles.push_back({{-0.2f + 0.1f * float(i % 5), -0.2f + 0.1f * float(i / 5), 0.0f}, velocity, 0.08f, 0.5f});
  MotionSums sums(w, h);
  splat_particle_motion(particles, camera, dt, sums);
  // Closed form: the frame spans 2 depth tan(fov / 2) world units vertically, times the aspect
  // across; image v runs down.
  const float span_v = 2.0f * depth * std::tan(glm::radians(fov) / 2.0f);
  const float span_u = span_v * float(w) / float(h);
  const float want_u = velocity.x * dt / span_u, want_v = -velocity.y * dt / span_v;
  const MotionField field = sums.field();
  const float strength = motion_strength({field});
  const MotionField decoded = decode_motion(encode_motion(field, strength), w, h, strength);
  const float quantum = strength / 255.0f + 1e-6f;
  int covered = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (sums.weight[size_t(y) * w + x] <= 0.0) continue;
      ++covered;
      ASSERT_NEAR(decoded.u(x, y), want_u, quantum) << x << "," << y;
      ASSERT_NEAR(decoded.v(x, y), want_v, quantum) << x << "," << y;
    }
  EXPECT_GT(covered, w * h / 4);
  // Unity's packing: R grows with u (rightward here: above the middle), G with the upward motion
  // (the particles fall: below the middle).
  const std::vector<uint8_t> rgba = encode_motion(field, strength);
  const size_t centre = (size_t(h / 2) * w + w / 2) * 4;
  EXPECT_GT(rgba[centre], 128);
  EXPECT_LT(rgba[centre + 1], 127);
  EXPECT_EQ(rgba[centre + 2], 0);
  EXPECT_EQ(rgba[centre + 3], 255);
}

// A Gaussian blob centred at (cx, cy) pixels on a w x h single-channel image.
BlendImage motion_test_blob(int w, int h, float cx, float cy) {
  BlendImage b{w, h, 1, std::vector<float>(size_t(w) * h)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float dx = float(x) + 0.5f - cx, dy = float(y) + 0.5f - cy;
      b.values[size_t(y) * w + x] = std::exp(-(dx * dx + dy * dy) / (2.0f * 3.0f * 3.0f));
    }
  return b;
}

TEST(FlipbookMotion, MotionVectorBlendOfATranslatedPatternBeatsTheLinearBlend) {
  const int w = 48, h = 48;
  const float step = 8.0f;  // pixels the blob moves right per frame
  const BlendImage a = motion_test_blob(w, h, 20.0f, 24.0f), b = motion_test_blob(w, h, 20.0f + step, 24.0f);
  MotionField m{w, h, std::vector<float>(size_t(w) * h * 2, 0.0f)};
  for (size_t i = 0; i < m.uv.size(); i += 2) m.uv[i] = step / float(w);
  for (float t : {0.25f, 0.5f, 0.75f}) {
    const BlendImage truth = motion_test_blob(w, h, 20.0f + t * step, 24.0f);
    const double linear = rmse(blend_linear(a, b, t), truth);
    const double motion = rmse(blend_motion_vectors(a, m, b, m, t), truth);
    // A uniform translation is carried exactly but for bilinear resampling of the blob.
    EXPECT_LT(motion, 0.1 * linear) << "t " << t << ": motion " << motion << ", linear " << linear;
    EXPECT_LT(motion, 0.01);
  }
}

TEST(FlipbookAtlas, ABakedAtlasHoldsTheFolderBakesFramesAndRisingMotion) {
  const SceneDescription scene = load_scene(test::scene_path("flipbook_fire.json"));
  FlipbookBakeOptions options;
  options.frames = 3;
  options.loop_blend = 1;
  options.width = 24;
  options.height = 36;
  const fs::path folder = test::scratch_dir("atlas_bake_folder");
  bake_flipbook(scene, options, folder.string());
  options.atlas_columns = 2;
  options.atlas_rows = 2;
  const fs::path atlas = test::scratch_dir("atlas_bake_atlas");
  bake_flipbook(scene, options, atlas.string());
  EXPECT_TRUE(fs::exists(atlas / "motion.png"));
  EXPECT_FALSE(fs::exists(atlas / "frame_0000.png"));
  const FlipbookFrames a = read_flipbook_folder(atlas.string()), b = read_flipbook_folder(folder.string());
  EXPECT_EQ(a.rgba, b.rgba);
  ASSERT_EQ(a.motion.size(), 3u);
  double v = 0.0;  // the flame rises: image v (down) averages below 0
  for (const MotionField& m : a.motion)
    for (size_t i = 1; i < m.uv.size(); i += 2) v += m.uv[i];
  EXPECT_LT(v, 0.0);
  options.atlas_rows = 1;
  EXPECT_THROW(bake_flipbook(scene, options, test::scratch_dir("atlas_bake_too_small").string()), UserError);
}

// A two-frame atlas folder: a 32 x 32 blob at x = 12 then x = 20 pixels (y = 16), its motion
// uniformly 8 pixels right per frame; with `centre_only`, one frame of the blob at x = 16.
std::string write_moving_blob_atlas(const std::string& name, bool centre_only) {
  const fs::path dir = test::scratch_dir(name);
  AtlasSidecar s;
  s.layout = {2, 1, 32, 32};
  s.frames = centre_only ? 1 : 2;
  std::vector<std::vector<uint8_t>> colour, motion;
  for (float cx : centre_only ? std::vector<float>{16.0f} : std::vector<float>{12.0f, 20.0f}) {
    const BlendImage blob = motion_test_blob(32, 32, cx, 16.0f);
    std::vector<uint8_t> rgb(32 * 32 * 3);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<uint8_t>(std::lround(255.0f * blob.values[i / 3]));
    colour.push_back(rgb);
    MotionField m{32, 32, std::vector<float>(32 * 32 * 2, 0.0f)};
    for (size_t i = 0; i < m.uv.size(); i += 2) m.uv[i] = 8.0f / 32.0f;
    motion.push_back(encode_motion(m, 0.5f));
  }
  write_png((dir / "atlas.png").string(), 64, 32, 3, pack_atlas(s.layout, colour, 3));
  if (!centre_only) {
    s.motion_image = "motion.png";
    s.motion_strength = 0.5f;
    write_png((dir / "motion.png").string(), 64, 32, 4, pack_atlas(s.layout, motion, 4));
  }
  std::ofstream((dir / "atlas.json").string()) << atlas_sidecar_json(s).dump(2);
  return dir.string();
}

// The x centroid (pixels) of the brightness of frame `frames` - 1 of one billboard showing
// `flipbook` straight ahead, the flipbook playing at 15 frames per second in a 30 fps scene.
double rendered_blob_centroid(const std::string& flipbook, int frames) {
  SceneDescription s;
  s.width = 64;
  s.height = 48;
  s.background = glm::vec3(0.0f);
  s.camera.position = {0.0f, 0.5f, 2.0f};
  s.camera.target = {0.0f, 0.5f, 0.0f};
  s.camera.fov_y_deg = 60.0f;
  FlipbookFire fire;
  fire.flipbook = flipbook;
  fire.width = 1.0f;
  fire.aspect = 1.0f;
  fire.frames_per_second = 15.0f;
  FlipbookGroup g;
  g.rows = 1;
  g.columns = 1;
  g.start_frames = {0};
  g.increments = {1};
  g.column_depths = {0.0f};
  fire.groups.push_back(g);
  s.fires.push_back(fire);
  RuntimeOptions o;
  o.readback = false;
  SceneRuntime r(s, o);
  for (int f = 0; f < frames; ++f) r.step();
  const std::vector<float> px = r.world().resource<GpuFrame>().eyes[0].scene->read_rgba();
  double sum = 0.0, weighted = 0.0;
  for (size_t i = 0; i < px.size(); i += 4) {
    sum += px[i];
    weighted += px[i] * (double((i / 4) % 64) + 0.5);
  }
  return weighted / sum;
}

TEST(FlipbookMotion, TheRendererCarriesTheFlameHalfWayBetweenFrames) {
  const std::string moving = write_moving_blob_atlas("blend_render_moving", false);
  const double at_frame = rendered_blob_centroid(moving, 1);  // step 0 exactly: frame 0 as it is
  const double half_way = rendered_blob_centroid(moving, 2);  // half way from frame 0 to frame 1
  const double truth = rendered_blob_centroid(write_moving_blob_atlas("blend_render_centre", true), 1);
  // The billboard is about 21 pixels wide: 4 texels of the 32 are about 2.6 pixels.
  EXPECT_GT(truth - at_frame, 2.0);
  EXPECT_NEAR(half_way, truth, 0.25) << "frame 0 at " << at_frame;
}

}  // namespace
}  // namespace pyro
