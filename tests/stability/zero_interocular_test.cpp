// Stability: zero interocular distance. The engine's eyes are the mono camera moved by -+I/2
// along its own right axis with off-axis frusta (engine/math/stereo_projection.h): with I = 0 both
// eyes are the mono camera exactly, and a stereo render gives two identical, finite images. The
// naive construction takes the baseline's direction from the eye positions,
// normalize(right_eye - left_eye), which is 0 / 0 = NaN when they coincide.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "components/frame_image.h"
#include "engine/math/camera_math.h"
#include "engine/math/stereo_projection.h"
#include "systems/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

TEST(StabilityZeroInterocular, EyesCoincideWithTheMonoCameraNaiveBaselineIsNaN) {
  const CameraFrame mono = make_camera_frame({1, 2, 6}, {0, 0.5f, 0}, {0, 1, 0}, 45.0f, 0.1f, 100.0f, 64, 48);
  const StereoParameters stereo{0.0f, 5.0f};
  const EyeMatrices left = make_eye_matrices(mono, stereo, Eye::left);
  const EyeMatrices right = make_eye_matrices(mono, stereo, Eye::right);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      EXPECT_TRUE(std::isfinite(left.view[c][r]) && std::isfinite(left.projection[c][r]));
      EXPECT_EQ(left.view[c][r], right.view[c][r]);
      EXPECT_EQ(left.projection[c][r], right.projection[c][r]);
    }
  // Naive: the baseline from the two eye positions.
  const glm::vec3 eye = mono.eye;
  const glm::vec3 naive_right = glm::normalize(eye - eye);
  EXPECT_TRUE(std::isnan(naive_right.x));
}

TEST(StabilityZeroInterocular, StereoRenderGivesTwoIdenticalFiniteViews) {
  SceneDescription s;
  s.width = 48;
  s.height = 36;
  s.camera.position = {0, 0, 6};
  s.camera.target = {0, 0, 0};
  CloudDescription cloud;
  cloud.count = 40;
  cloud.radius = 0.5f;
  cloud.density = 0.4f;
  cloud.box_min = {-1.5f, -1.0f, -1.0f};
  cloud.box_max = {1.5f, 1.0f, 1.0f};
  s.clouds.push_back(cloud);
  RuntimeOptions o;
  o.stereo_mode = StereoMode::left_right;
  o.interocular = 0.0f;
  SceneRuntime run(s, o);
  run.step();
  const FrameImage& img = run.image();
  ASSERT_EQ(img.rgba.size(), img.right_rgba.size());
  for (float v : img.rgba) ASSERT_TRUE(std::isfinite(v));
  EXPECT_EQ(img.rgba, img.right_rgba);
}

}  // namespace
}  // namespace pyro
