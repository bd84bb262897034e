// The fog scene hides the water tower partly: some of the tower shows through, some is lost.
// Per pixel on the tower, the visible fraction is |fog - fog without tower| / |clear - clear
// without tower|: how much of the tower's contrast against the ground survives the fog.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "components/frame_image.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

std::vector<float> render_fog_occlusion(SceneDescription s) {
  RuntimeOptions o;
  o.width_override = 240;
  o.height_override = 180;
  SceneRuntime r(s, o);
  r.step();
  return r.image().rgba;
}

float luminance(const std::vector<float>& img, size_t pixel) {
  return 0.2126f * img[pixel * 4] + 0.7152f * img[pixel * 4 + 1] + 0.0722f * img[pixel * 4 + 2];
}

TEST(FogOcclusion, WaterTowerIsPartlyHiddenByFog) {
  const SceneDescription fog = load_scene(test::scene_path("fog.json"));
  SceneDescription fog_no_tower = fog, clear = fog, clear_no_tower = fog;
  auto drop_tower = [](SceneDescription& s) {
    std::erase_if(s.meshes, [](const MeshDescription& m) { return m.kind == MeshKind::water_tower; });
  };
  drop_tower(fog_no_tower);
  drop_tower(clear_no_tower);
  clear.clouds.clear();
  clear_no_tower.clouds.clear();
  const auto a = render_fog_occlusion(fog), b = render_fog_occlusion(fog_no_tower), c = render_fog_occlusion(clear), d = render_fog_occlusion(clear_no_tower);

  std::vector<float> visible;
  for (size_t p = 0; p < a.size() / 4; ++p) {
    const float contrast = std::abs(luminance(c, p) - luminance(d, p));
    if (contrast < 0.05f) continue;  // not on the tower (or the tower matches the ground)
    visible.push_back(std::abs(luminance(a, p) - luminance(b, p)) / contrast);
  }
  ASSERT_GT(visible.size(), 500u) << "the tower should cover a good part of the frame";
  std::sort(visible.begin(), visible.end());
  const float median = visible[visible.size() / 2];
  const auto count_below = [&](float t) {
    return static_cast<double>(std::lower_bound(visible.begin(), visible.end(), t) - visible.begin()) /
           visible.size();
  };
  EXPECT_GT(median, 0.1f) << "the tower should still show through";
  EXPECT_LT(median, 0.9f) << "the fog should hide a good part of the tower";
  EXPECT_GT(count_below(0.35f), 0.1) << "some of the tower should be mostly hidden";
  EXPECT_LT(count_below(0.65f), 0.9) << "some of the tower should be mostly visible";
}

}  // namespace
}  // namespace pyro
