// A two-frame particle sequence drawn by the GL splats at w = 0.25 between its frames: one white
// particle over black at the image centre, frame 1 of centre opacity rho_a, frame 2 of rho_b.
// Drawn with optical depths scaled by 1 - w and w (systems/volume_sequence/sequence_frames.h),
// the centre pixel's opacity is 1 - (1 - rho_a)^(1-w) (1 - rho_b)^w = 1 - exp(-((1 - w) tau_a +
// w tau_b)): the linear interpolation of the density field, in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "components/frame_image.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/particle_sequence_fixture.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(VolumeSequenceCrossFade, CentrePixelMatchesTheInterpolatedOpticalDepth) {
  const auto dir = test::scratch_dir("crossfade_render");
  const double rho_a = 0.5, rho_b = 0.9;
  test::write_test_sequence(dir / "s.pyroseq",
                            {{test::test_particle(3, 3, 3, 0.8f, float(rho_a))},
                             {test::test_particle(3, 3, 3, 0.8f, float(rho_b))}},
                            7.5);
  // 7.5 source fps in a 30 fps scene: frame 1 is source position 0.25.
  const SceneDescription scene = parse_scene(
      R"({"output": {"width": 161, "height": 121, "fps": 30}, "background": [0, 0, 0],
          "camera": {"position": [0, 0, 0], "target": [0, 0, -1], "fov_y_deg": 40},
          "volumes": [{"file": "s.pyroseq", "position": [0, 0, -5]}]})",
      (dir / "scene.json").string());
  RuntimeOptions o;
  o.readback = true;
  SceneRuntime runtime(scene, o);
  runtime.draw_frame(1);
  const FrameImage& img = runtime.image();
  const double got = img.rgba[(std::size_t(img.height / 2) * img.width + img.width / 2) * 4];
  const double w = 0.25;
  const double expected = 1.0 - std::pow(1.0 - rho_a, 1.0 - w) * std::pow(1.0 - rho_b, w);
  // The footprint's bilinear lookup (<= 2.1e-3 rho) and half-float storage, per particle.
  EXPECT_NEAR(got, expected, 6e-3);
  // Either frame alone, or the opacities blended linearly, is far off.
  EXPECT_GT(std::abs(got - ((1 - w) * rho_a + w * rho_b)), 0.05);
  runtime.draw_frame(4);  // position 1: frame 2 alone
  const double alone = runtime.image().rgba[(std::size_t(img.height / 2) * img.width + img.width / 2) * 4];
  EXPECT_NEAR(alone, rho_b, 4e-3);
}

}  // namespace
}  // namespace pyro
