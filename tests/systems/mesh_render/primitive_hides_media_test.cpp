// A box primitive hides the medium behind it: the camera looks down -z at a red particle whose
// left half is behind a box (x in [-2, 0]); there the image is the box's alone, byte for byte,
// while the particle's right half shows beside it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "components/frame_image.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

constexpr int kBoxTestWidth = 64, kBoxTestHeight = 48;

SceneDescription box_before_particle(bool box, bool particle) {
  SceneDescription s;
  s.width = kBoxTestWidth;
  s.height = kBoxTestHeight;
  s.camera.position = {0.0f, 1.0f, 6.0f};
  s.camera.target = {0.0f, 1.0f, 0.0f};
  s.camera.fov_y_deg = 30.0f;
  if (box) {
    MeshDescription m;
    m.kind = MeshKind::box;
    m.size = {2.0f, 2.0f, 0.5f};
    m.position = {-1.0f, 0.0f, 0.0f};
    m.color = {0.1f, 0.6f, 0.1f};
    s.meshes.push_back(m);
  }
  if (particle) {
    CloudDescription c;
    c.count = 1;
    c.radius = 1.0f;
    c.density = 1.0f;
    c.color = {1.0f, 0.0f, 0.0f};
    c.box_min = {-1e-4f, 1.0f - 1e-4f, -3.0f - 1e-4f};
    c.box_max = {1e-4f, 1.0f + 1e-4f, -3.0f + 1e-4f};
    s.clouds.push_back(c);
  }
  return s;
}

std::vector<float> render_box_scene(bool box, bool particle) {
  SceneRuntime r(box_before_particle(box, particle));
  r.step();
  return r.image().rgba;
}

TEST(PrimitiveHidesMedia, ABoxHidesTheParticleBehindItAndNotBeside) {
  const std::vector<float> empty = render_box_scene(false, false), box = render_box_scene(true, false),
                           particle = render_box_scene(false, true), both = render_box_scene(true, true);
  ASSERT_EQ(both.size(), size_t(kBoxTestWidth) * kBoxTestHeight * 4);
  int covered = 0, beside = 0;
  double covered_change = 0.0, beside_change = 0.0;
  for (int y = 0; y < kBoxTestHeight; ++y) {
    for (int x = 0; x < kBoxTestWidth; ++x) {
      const size_t i = (size_t(y) * kBoxTestWidth + x) * 4;
      if (std::abs(particle[i] - empty[i]) < 0.05f) continue;  // not the particle's
      double change = 0.0;
      for (int c = 0; c < 3; ++c) change = std::max(change, double(std::abs(both[i + c] - box[i + c])));
      if (x < kBoxTestWidth / 2 - 2) {
        ++covered;
        covered_change = std::max(covered_change, change);
        EXPECT_GT(std::abs(box[i + 1] - empty[i + 1]), 0.05f) << "the box must cover pixel " << x << ", " << y;
      } else if (x > kBoxTestWidth / 2 + 2) {
        ++beside;
        beside_change = std::max(beside_change, change);
      }
    }
  }
  ASSERT_GT(covered, 30);
  ASSERT_GT(beside, 30);
  EXPECT_EQ(covered_change, 0.0) << "the particle behind the box must not show through it";
  EXPECT_GT(beside_change, 0.3) << "the particle beside the box must show";
}

}  // namespace
}  // namespace pyro
