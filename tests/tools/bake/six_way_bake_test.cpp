// A six-way bake by the engine of one white Gaussian particle lit with shadows, seen from the
// front on black, whose faces are known: the particle's self-shadow makes the side towards each
// face's light the brighter one (right-lit brighter on the right, left-lit its mirror image,
// top-lit brighter at the top), and at its centre every face is exp(-tau0 / 2) = sqrt(1 - rho)
// (the lit splat's closed form at its closest point: half its column towards any light,
// docs/lighting.md) under alpha rho (the lit splat's opacity 1 - exp(-tau0)). The textures are
// read back from the folder the bake wrote, with its sidecar.
#include "tools/bake/six_way_bake.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/io/png_file.h"
#include "systems/flipbook_fire/flipbook_folder.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/bake/six_way_folder.h"
#include "tests/support/one_particle_scene.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

constexpr int kSixWayBakeSize = 32;
constexpr float kSixWayBakeDensity = 0.6f;

struct SixWayBakeTextures {
  PngImage a, b;
  nlohmann::json sidecar;
  FlipbookFrames folder_a;  // six_way_a read as a flipbook folder
  std::string out;
};

const SixWayBakeTextures& baked_particle() {
  static const SixWayBakeTextures baked = [] {
    SceneDescription scene = test::one_particle_scene({0.0f, 0.0f, -3.0f}, 0.5f, kSixWayBakeDensity,
                                                      kSixWayBakeSize, kSixWayBakeSize, 30.0f);
    scene.file = "one_particle";
    scene.shadows = ShadowSettings{};
    scene.shadows->method = ShadowMethod::rays;
    SixWayBakeOptions options;
    options.frames = 1;
    options.loop_blend = 0;
    options.width = options.height = kSixWayBakeSize;
    check_six_way_bake(scene, options, "");
    const std::string out = (test::scratch_dir("six_way_bake") / "bake").string();
    SceneRuntime runtime(scene, six_way_runtime_options(options));
    bake_six_way(runtime, options, out);
    return SixWayBakeTextures{read_png(out + "/six_way_a/frame_0000.png"),
                              read_png(out + "/six_way_b/frame_0000.png"),
                              nlohmann::json::parse(read_text_file(out + "/six_way.json")),
                              read_flipbook_folder(out + "/six_way_a"), out};
  }();
  return baked;
}

int six_way_channel(const PngImage& image, int x, int y, int c) {
  return image.pixels[(static_cast<size_t>(y) * image.width + x) * 4 + c];
}

TEST(SixWayBake, WritesTwoRgbaTexturesAndTheirSidecar) {
  const SixWayBakeTextures& t = baked_particle();
  EXPECT_EQ(t.a.channels, 4);
  EXPECT_EQ(t.b.channels, 4);
  EXPECT_EQ(t.a.width, kSixWayBakeSize);
  EXPECT_EQ(t.sidecar["textures"]["a"]["folder"], "six_way_a");
  EXPECT_EQ(t.sidecar["color_space"], "linear");
  EXPECT_EQ(t.sidecar["premultiplied"], false);
  EXPECT_EQ(t.folder_a.files.size(), 1u);  // a flipbook folder as the flame bake's
  EXPECT_EQ(t.folder_a.width, kSixWayBakeSize);
}

TEST(SixWayBake, AFrameReadsBackFromTheFolder) {
  const SixWayBakeTextures& t = baked_particle();
  const SixWayTextures read = read_six_way_frame(t.out, 0);
  EXPECT_EQ(read.a, t.a.pixels);
  EXPECT_EQ(read.b, t.b.pixels);
  EXPECT_THROW(read_six_way_frame(t.out, 1), UserError);  // one frame baked
}

TEST(SixWayBake, AnUnlitSceneIsRefusedNamingTheKey) {
  SceneDescription scene = test::one_particle_scene({0.0f, 0.0f, -3.0f}, 0.5f, 0.5f, 8, 8, 30.0f);
  scene.file = "unlit.json";
  try {
    check_six_way_bake(scene, SixWayBakeOptions{}, "");
    FAIL() << "an unlit scene was accepted";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("/shadows"), std::string::npos) << e.what();
  }
}

TEST(SixWayBake, TheCentreHoldsTheClosedForm) {
  const SixWayBakeTextures& t = baked_particle();
  // The particle is centred between the four middle pixels: their mean.
  const auto centre = [&](const PngImage& image, int c) {
    const int m = kSixWayBakeSize / 2;
    return (six_way_channel(image, m - 1, m - 1, c) + six_way_channel(image, m, m - 1, c) +
            six_way_channel(image, m - 1, m, c) + six_way_channel(image, m, m, c)) /
           (4.0 * 255.0);
  };
  EXPECT_NEAR(centre(t.a, 3), kSixWayBakeDensity, 0.03);  // alpha
  const double face = std::sqrt(1.0 - kSixWayBakeDensity);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(centre(t.a, c), face, 0.04) << "A channel " << c;
    EXPECT_NEAR(centre(t.b, c), face, 0.04) << "B channel " << c;
  }
  EXPECT_EQ(centre(t.b, 3), 0.0);  // no emission
}

TEST(SixWayBake, EachSideFacesItsLight) {
  const SixWayBakeTextures& t = baked_particle();
  const int m = kSixWayBakeSize / 2, d = 5;  // half a radius either side of the centre
  const int right = m + d - 1, left = m - d, top = m - d, bottom = m + d - 1;
  // A.r: lit from the right; B.r its mirror image.
  EXPECT_GT(six_way_channel(t.a, right, m, 0), six_way_channel(t.a, left, m, 0) + 20);
  EXPECT_NEAR(six_way_channel(t.a, right, m, 0), six_way_channel(t.b, left, m, 0), 2);
  EXPECT_NEAR(six_way_channel(t.a, left, m, 0), six_way_channel(t.b, right, m, 0), 2);
  // A.g: lit from the top (row 0 is the top); B.g from the bottom.
  EXPECT_GT(six_way_channel(t.a, m, top, 1), six_way_channel(t.a, m, bottom, 1) + 20);
  EXPECT_NEAR(six_way_channel(t.a, m, top, 1), six_way_channel(t.b, m, bottom, 1), 2);
}

}  // namespace
}  // namespace pyro
