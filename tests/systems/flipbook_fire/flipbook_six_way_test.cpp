// Six-way flipbooks drawn by the engine: a bake folder (six_way.json, six_way_a/, six_way_b/)
// read as lightmaps, faded in alpha alone, and relit on the GPU under the scene's light, checked
// against the CPU blend (systems/flipbook_fire/six_way_basis.h) and the premultiplied over
// blend, for the six axes and the eight directions between them.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "components/gpu_frame.h"
#include "engine/core/user_error.h"
#include "engine/io/png_file.h"
#include "systems/flipbook_fire/flipbook_emission.h"
#include "systems/flipbook_fire/flipbook_folder.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "systems/flipbook_fire/six_way_basis.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace flipbook_six_way_test {
namespace {

namespace fs = std::filesystem;

constexpr int kSixWayWidth = 64, kSixWayHeight = 48;
constexpr float kSixWayBackground = 0.2f;
// Each face a different value, so that a face read for another shows: right, top, back, left,
// bottom, front (SixWayFace order), then alpha and emissive.
constexpr std::array<uint8_t, 6> kFaces{230, 180, 40, 90, 20, 140};
constexpr uint8_t kAlpha = 204, kEmissive = 0;

// A bake folder of `frames` uniform frames with the faces above.
std::string six_way_folder(const std::string& name, int frames = 2, bool with_b = true) {
  const fs::path dir = test::scratch_dir(name);
  fs::create_directories(dir / "six_way_a");
  if (with_b) fs::create_directories(dir / "six_way_b");
  const std::vector<uint8_t> a = {kFaces[0], kFaces[1], kFaces[2], kAlpha};
  const std::vector<uint8_t> b = {kFaces[3], kFaces[4], kFaces[5], kEmissive};
  std::vector<uint8_t> pa, pb;
  for (int i = 0; i < 8 * 8; ++i) {
    pa.insert(pa.end(), a.begin(), a.end());
    pb.insert(pb.end(), b.begin(), b.end());
  }
  for (int f = 0; f < frames; ++f) {
    char file[32];
    std::snprintf(file, sizeof file, "frame_%04d.png", f);
    write_png((dir / "six_way_a" / file).string(), 8, 8, 4, pa);
    if (with_b) write_png((dir / "six_way_b" / file).string(), 8, 8, 4, pb);
  }
  std::ofstream(dir / "six_way.json") << "{\"frames\": " << frames << "}\n";
  return dir.string();
}

SixWayValues faces() {
  SixWayValues v{};
  for (int i = 0; i < kSixWayFaces; ++i) v[static_cast<size_t>(i)] = kFaces[static_cast<size_t>(i)] / 255.0f;
  return v;
}

// One billboard 1 x 1 straight ahead of a camera 2 units away looking along -z, so that the
// fire's frame is the world's: right +x, up +y, toward the viewer +z.
SceneDescription six_way_scene(const std::string& folder, const glm::vec3& towards_light) {
  SceneDescription s;
  s.width = kSixWayWidth;
  s.height = kSixWayHeight;
  s.background = glm::vec3(kSixWayBackground);
  s.camera.position = {0.0f, 0.5f, 2.0f};
  s.camera.target = {0.0f, 0.5f, 0.0f};
  s.camera.fov_y_deg = 60.0f;
  s.directional_lights[0].direction = -towards_light;
  s.directional_lights[0].color = {1.0f, 0.8f, 0.6f};
  s.directional_lights[0].intensity = 1.0f;
  s.ambient_lights[0].color = {0.05f, 0.05f, 0.1f};
  FlipbookFire fire;
  fire.flipbook = folder;
  fire.width = 1.0f;
  fire.aspect = 1.0f;
  fire.blend = FlipbookBlend::one_minus_destination;  // not used: six-way smoke is blended over
  FlipbookGroup g;
  g.rows = 1;
  g.columns = 1;
  g.column_depths = {0.0f};
  fire.groups.push_back(g);
  s.fires.push_back(fire);
  return s;
}

glm::vec3 six_way_centre_pixel(SceneRuntime& r) {
  const std::vector<float> px = r.world().resource<GpuFrame>().eyes[0].scene->read_rgba();
  const size_t i = (static_cast<size_t>(kSixWayHeight / 2) * kSixWayWidth + kSixWayWidth / 2) * 4;
  return {px[i], px[i + 1], px[i + 2]};
}

}  // namespace

TEST(FlipbookSixWay, BakeFolderIsReadAsTwoLightmaps) {
  const FlipbookFrames f = read_flipbook_folder(six_way_folder("six_way_read", 3));
  ASSERT_TRUE(f.six_way());
  ASSERT_EQ(f.rgba.size(), 3u);
  ASSERT_EQ(f.six_way_b.size(), 3u);
  EXPECT_EQ(f.rgba[2][0], kFaces[0]);
  EXPECT_EQ(f.rgba[2][3], kAlpha);
  EXPECT_EQ(f.six_way_b[1][2], kFaces[5]);
  // Baked smoke gives off no light.
  const FlipbookEmission e = flipbook_emission(f, FlipbookBlend::linear_alpha);
  EXPECT_EQ(e.frame_radiance[0], glm::vec3(0.0f));
}

TEST(FlipbookSixWay, FadeThinsTheSmokeWithoutDarkeningIt) {
  FlipbookFrames f = read_flipbook_folder(six_way_folder("six_way_fade", 1));
  FlipbookPreparation p;
  p.base_line = 0.5f;  // the bottom half transparent
  prepare_flipbook(f, p);
  const size_t bottom = static_cast<size_t>(7 * 8) * 4;
  EXPECT_EQ(f.rgba[0][bottom + 3], 0);
  EXPECT_EQ(f.rgba[0][bottom + 0], kFaces[0]);
  EXPECT_EQ(f.six_way_b[0][bottom + 0], kFaces[3]);
}

TEST(FlipbookSixWay, MissingLightmapOrCountIsAUserError) {
  try {
    read_flipbook_folder(six_way_folder("six_way_no_b", 2, false));
    FAIL() << "a bake without six_way_b was read";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("six_way_b"), std::string::npos) << e.what();
  }
  const std::string folder = six_way_folder("six_way_count", 2);
  std::ofstream(fs::path(folder) / "six_way.json") << "{\"frames\": 5}\n";
  try {
    read_flipbook_folder(folder);
    FAIL() << "a frame count the folders do not hold was accepted";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("six_way.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected 5 frames"), std::string::npos) << e.what();
  }
}

TEST(FlipbookSixWay, GpuRelightMatchesTheBlendForAxesAndDiagonals) {
  const std::string folder = six_way_folder("six_way_render");
  std::vector<glm::vec3> lights = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int k = 0; k < 8; ++k)
    lights.push_back(glm::normalize(glm::vec3(k & 1 ? -1 : 1, k & 2 ? -1 : 1, k & 4 ? -1 : 1)));
  const glm::vec3 light_color{1.0f, 0.8f, 0.6f}, ambient{0.05f, 0.05f, 0.1f};
  const float alpha = kAlpha / 255.0f;
  for (const glm::vec3& w : lights) {
    RuntimeOptions o;
    o.readback = false;
    SceneRuntime r(six_way_scene(folder, w), o);
    r.step();
    const float lighting = six_way_relight(faces(), w);
    const glm::vec3 expected = (light_color * lighting + ambient) * alpha + kSixWayBackground * (1.0f - alpha);
    const glm::vec3 c = six_way_centre_pixel(r);
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(c[ch], expected[ch], 3e-3f) << "towards the light " << w.x << " " << w.y << " " << w.z;
  }
}

}  // namespace flipbook_six_way_test
}  // namespace pyro
