// Stereo eye frames (parallel axes, off-axis frusta) over the whole view volume: no vertical
// parallax, horizontal parallax as its closed form, nothing at all without an interocular.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/math/stereo_parallax_analysis.h"
#include "engine/math/camera_math.h"
#include "engine/math/stereo_projection.h"

namespace pyro {
namespace {

// An oblique camera (not axis-aligned): float rounding shows up in every matrix entry.
CameraFrame oblique_camera() {
  return make_camera_frame({3.0f, 2.5f, 7.0f}, {-1.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 45.0f, 0.1f,
                           200.0f, 1024, 768);
}

TEST(StereoParallaxAnalysis, NoVerticalParallaxAndTheClosedFormHorizontalParallax) {
  for (const CameraFrame& mono :
       {oblique_camera(), make_camera_frame({0.0f, 1.5f, 8.0f}, {0.0f, 1.5f, 0.0f},
                                            {0.0f, 1.0f, 0.0f}, 45.0f, 0.1f, 200.0f, 1024, 768)}) {
    for (const StereoParameters stereo :
         {StereoParameters{0.065f, 5.0f}, StereoParameters{0.3f, 2.0f}}) {
      const StereoParallaxReport r = analyze_stereo_parallax(mono, stereo, 21);
      EXPECT_EQ(r.points, 21 * 21 * 21);
      // The double path resolves the construction: both bars are 1e-6 px.
      EXPECT_LE(r.max_vertical_parallax, 1e-6);
      EXPECT_LE(r.max_horizontal_parallax_error, 1e-6);
      // The range runs from the near plane's crossed parallax to the far plane's uncrossed one.
      // (The grid's end points lie at mono.near and mono.far along the float forward axis, whose
      // direction differs from the eye frames' double one by ~1e-8: 3e-5 px at the near plane.)
      EXPECT_NEAR(r.min_horizontal_parallax, horizontal_parallax_pixels(mono, stereo, mono.near),
                  1e-3);
      EXPECT_NEAR(r.max_horizontal_parallax, horizontal_parallax_pixels(mono, stereo, mono.far),
                  1e-3);
      // The float path (the renderer's matrices) carries float rounding only: make_eye_frame
      // rounds the double construction, so its rotation rows are identical for both eyes
      // (measured 0 px vertical; a float lookAt per eye gave 7e-3 px for this camera).
      EXPECT_LE(r.max_vertical_parallax_float, 1e-3);
      EXPECT_LE(r.max_horizontal_parallax_error_float, 0.05);
    }
  }
}

TEST(StereoParallaxAnalysis, ZeroInterocularGivesZeroParallaxEverywhere) {
  const StereoParallaxReport r = analyze_stereo_parallax(oblique_camera(), {0.0f, 5.0f}, 17);
  EXPECT_EQ(r.max_vertical_parallax, 0.0);
  EXPECT_EQ(r.max_horizontal_parallax_error, 0.0);
  EXPECT_EQ(r.min_horizontal_parallax, 0.0);
  EXPECT_EQ(r.max_horizontal_parallax, 0.0);
  EXPECT_EQ(r.max_vertical_parallax_float, 0.0);
  EXPECT_EQ(r.max_horizontal_parallax_error_float, 0.0);
}

TEST(StereoParallaxAnalysis, ZeroParallaxPlaneProjectsToTheSamePixelInBothEyes) {
  const CameraFrame mono = oblique_camera();
  const StereoParameters stereo{0.065f, 5.0f};
  const EyeMatrices left = make_eye_matrices(mono, stereo, Eye::left);
  const EyeMatrices right = make_eye_matrices(mono, stereo, Eye::right);
  const glm::dvec3 p = glm::dvec3(mono.eye) + 5.0 * glm::dvec3(mono.forward) +
                       0.7 * glm::dvec3(mono.right) - 0.4 * glm::dvec3(mono.up);
  const glm::dvec2 a = project_to_pixels(left.view_projection, mono.width, mono.height, p);
  const glm::dvec2 b = project_to_pixels(right.view_projection, mono.width, mono.height, p);
  EXPECT_NEAR(a.x, b.x, 1e-6);
  EXPECT_NEAR(a.y, b.y, 1e-9);
  EXPECT_NEAR(glm::length(right.eye - left.eye), static_cast<double>(stereo.interocular), 1e-12);
}

TEST(StereoParallaxAnalysis, EyeFrameIsTheDoubleConstructionRoundedToFloat) {
  const CameraFrame mono = oblique_camera();
  const StereoParameters stereo{0.065f, 5.0f};
  for (Eye eye : {Eye::left, Eye::right}) {
    const EyeMatrices m = make_eye_matrices(mono, stereo, eye);
    const CameraFrame f = make_eye_frame(mono, stereo, eye);
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        EXPECT_EQ(f.view[c][r], static_cast<float>(m.view[c][r]));
        EXPECT_EQ(f.projection[c][r], static_cast<float>(m.projection[c][r]));
      }
    }
    EXPECT_EQ(f.eye, glm::vec3(m.eye));
  }
}

TEST(StereoParallaxAnalysis, RefusesTooFewSamples) {
  EXPECT_THROW(analyze_stereo_parallax(oblique_camera(), {}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace pyro
