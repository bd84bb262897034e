// Stability: zero interocular distance. The engine's eyes are the mono camera moved by -+I/2
// along its own right axis with off-axis frusta (engine/math/stereo_projection.h): with I = 0 both
// eyes are the mono camera exactly, every point has zero parallax, and a stereo render gives two
// identical, finite images. A construction that takes the baseline's direction from the eye
// positions, normalize(right_eye - left_eye), would divide 0 by 0 here and make every matrix NaN.
// The tests run the engine's stereo camera: the camera system on a world with a StereoCamera of
// interocular 0, the double-precision eye matrices, and a whole stereo render.
#include <gtest/gtest.h>

#include <cmath>

#include "components/camera.h"
#include "components/frame_image.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "components/view.h"
#include "engine/ecs/world.h"
#include "engine/math/camera_math.h"
#include "engine/math/stereo_projection.h"
#include "systems/camera/camera_system.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

template <class M>
void expect_same_finite_matrix(const M& a, const M& b, const char* what) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      EXPECT_TRUE(std::isfinite(a[c][r])) << what << " [" << c << "][" << r << "]";
      EXPECT_EQ(a[c][r], b[c][r]) << what << " [" << c << "][" << r << "]";
    }
}

TEST(StabilityZeroInterocular, StereoCameraEyesAreTheMonoCameraWithZeroParallax) {
  ecs::World w;
  RenderSettings& settings = w.set_resource<RenderSettings>();
  settings.width = 64;
  settings.height = 48;
  settings.stereo_mode = StereoMode::left_right;
  const ecs::Entity cam = w.create();
  w.emplace<Camera>(cam, Camera{{1, 2, 6}, {0, 0.5f, 0}, {0, 1, 0}, 45, 0.1f, 100, 0});
  w.emplace<StereoCamera>(cam, StereoCamera{StereoParameters{0.0f, 5.0f}, EyeOrder::left_right});
  ecs::run_system_once(stereo_camera_system(), w);
  const View& view = w.resource<View>();
  ASSERT_EQ(view.eyes.size(), 2u);
  const CameraFrame& left = view.eyes[0];
  const CameraFrame& right = view.eyes[1];
  // Both eyes sit exactly at the mono eye, with bit-identical matrices. (The eyes' matrices are
  // made in double and rounded, the mono frame's in float: they agree to float rounding.)
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(left.eye[k], view.frame.eye[k]) << k;
    EXPECT_EQ(right.eye[k], view.frame.eye[k]) << k;
  }
  expect_same_finite_matrix(left.view, right.view, "view");
  expect_same_finite_matrix(left.projection, right.projection, "projection");
  expect_same_finite_matrix(left.view_projection, right.view_projection, "view_projection");
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(left.view[c][r], view.frame.view[c][r], 1e-5f) << c << r;
      EXPECT_NEAR(left.projection[c][r], view.frame.projection[c][r], 1e-5f) << c << r;
    }
  // Zero parallax everywhere in the view volume: both eyes put every point on the same pixel.
  for (float depth : {0.2f, 1.0f, 5.0f, 20.0f, 90.0f})
    for (float sx : {-0.4f, 0.0f, 0.3f})
      for (float sy : {-0.3f, 0.0f, 0.35f}) {
        const glm::vec3 p = view.frame.eye + depth * view.frame.forward +
                            depth * sx * view.frame.right + depth * sy * view.frame.up;
        const glm::vec2 l = project_to_pixels(left, p), r = project_to_pixels(right, p);
        ASSERT_TRUE(std::isfinite(l.x) && std::isfinite(l.y)) << depth;
        EXPECT_EQ(l.x, r.x) << "horizontal parallax at depth " << depth;
        EXPECT_EQ(l.y, r.y) << "vertical parallax at depth " << depth;
      }
  for (double z : {0.2, 5.0, 90.0})
    EXPECT_EQ(horizontal_parallax_pixels(view.frame, StereoParameters{0.0f, 5.0f}, z), 0.0) << z;
}

TEST(StabilityZeroInterocular, DoublePrecisionEyesCoincideWithTheMonoCamera) {
  const CameraFrame mono = make_camera_frame({1, 2, 6}, {0, 0.5f, 0}, {0, 1, 0}, 45.0f, 0.1f, 100.0f, 64, 48);
  const StereoParameters stereo{0.0f, 5.0f};
  const EyeMatrices left = make_eye_matrices(mono, stereo, Eye::left);
  const EyeMatrices right = make_eye_matrices(mono, stereo, Eye::right);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(left.eye[k], right.eye[k]) << k;
    EXPECT_EQ(left.eye[k], double(mono.eye[k])) << k;
  }
  expect_same_finite_matrix(left.view, right.view, "view");
  expect_same_finite_matrix(left.projection, right.projection, "projection");
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
  ASSERT_EQ(img.rgba.size(), size_t(48 * 36 * 4));
  ASSERT_EQ(img.right_rgba.size(), img.rgba.size());
  for (float v : img.rgba) ASSERT_TRUE(std::isfinite(v));
  EXPECT_EQ(img.rgba, img.right_rgba);
}

}  // namespace
}  // namespace pyro
