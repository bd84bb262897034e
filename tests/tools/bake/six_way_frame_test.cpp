// Six-way lightmaps on made-up inputs whose answer is known per face: the channel packing of
// Unity VFX Graph (A = right, top, back, alpha; B = left, bottom, front, emissive), the straight
// (un-premultiplied) faces, the blend's closed form for axis and diagonal lights, and where each
// face's light is for a camera.
#include "tools/bake/six_way_frame.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tools/bake/six_way_passes.h"

namespace pyro {
namespace {

// A 2x1 frame's renders: face i lit to value (i + 1) / 8 (straight) under opacity 0.5 in pixel
// 0, and opacity 0 in pixel 1 (no medium).
SixWayFrame made_up_six_way_frame() {
  std::array<RgbImage, kSixWayFaces> faces;
  RgbImage opacity{2, 1, {0.5f, 0.5f, 0.5f, 0.0f, 0.0f, 0.0f}};
  for (int i = 0; i < kSixWayFaces; ++i) {
    const float premultiplied = 0.5f * static_cast<float>(i + 1) / 8.0f;
    faces[i] = RgbImage{2, 1, {premultiplied, premultiplied, premultiplied, 0.0f, 0.0f, 0.0f}};
  }
  return six_way_frame_from_renders(faces, opacity);
}

uint8_t six_way_byte(float v) { return static_cast<uint8_t>(std::lround(v * 255.0f)); }

TEST(SixWayPacking, ChannelsFollowUnitysLightmapsAAndB) {
  SixWayFrame frame = made_up_six_way_frame();
  frame.emissive[0] = 0.25f;
  const SixWayTextures t = pack_six_way(frame);
  const auto face = [](SixWayFace f) {
    return six_way_byte(static_cast<float>(static_cast<int>(f) + 1) / 8.0f);
  };
  EXPECT_EQ(t.a[0], face(SixWayFace::right));
  EXPECT_EQ(t.a[1], face(SixWayFace::top));
  EXPECT_EQ(t.a[2], face(SixWayFace::back));
  EXPECT_EQ(t.a[3], six_way_byte(0.5f));  // alpha
  EXPECT_EQ(t.b[0], face(SixWayFace::left));
  EXPECT_EQ(t.b[1], face(SixWayFace::bottom));
  EXPECT_EQ(t.b[2], face(SixWayFace::front));
  EXPECT_EQ(t.b[3], six_way_byte(0.25f));  // emissive
  for (int c = 0; c < 4; ++c) {            // no medium: nothing lit, transparent
    EXPECT_EQ(t.a[4 + c], 0);
    EXPECT_EQ(t.b[4 + c], 0);
  }
  const SixWayFrame back = unpack_six_way(t);
  for (int i = 0; i < kSixWayFaces; ++i)
    EXPECT_NEAR(back.faces[i][0], (i + 1) / 8.0f, 0.5f / 255.0f + 1e-6f);
}

TEST(SixWayRelight, AnAxisLightGivesItsFaceExactly) {
  const SixWayValues faces{0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};
  for (int i = 0; i < kSixWayFaces; ++i) {
    const SixWayFace f = static_cast<SixWayFace>(i);
    EXPECT_FLOAT_EQ(six_way_relight(faces, six_way_towards_light(f)), faces[i]);
  }
  // The faces' lights: right +x, top +y, back -z (behind the smoke), front +z (the viewer's side).
  EXPECT_EQ(six_way_towards_light(SixWayFace::right), glm::vec3(1, 0, 0));
  EXPECT_EQ(six_way_towards_light(SixWayFace::bottom), glm::vec3(0, -1, 0));
  EXPECT_EQ(six_way_towards_light(SixWayFace::back), glm::vec3(0, 0, -1));
  EXPECT_EQ(six_way_towards_light(SixWayFace::front), glm::vec3(0, 0, 1));
}

TEST(SixWayRelight, DiagonalLightsBlendBySquaredComponents) {
  const SixWayValues faces{0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};  // right top back left bottom front
  // (1, 1, 1)/sqrt 3: right, top and front, a third each.
  EXPECT_NEAR(six_way_relight(faces, {1, 1, 1}), (0.1f + 0.2f + 0.6f) / 3.0f, 1e-6);
  // (-1, -1, -1)/sqrt 3: left, bottom and back.
  EXPECT_NEAR(six_way_relight(faces, {-1, -1, -1}), (0.4f + 0.5f + 0.3f) / 3.0f, 1e-6);
  // (0.6, 0, -0.8): 0.36 right + 0.64 back (not 0.6 / 0.8: Unity squares the components).
  EXPECT_NEAR(six_way_relight(faces, {0.6f, 0.0f, -0.8f}), 0.36f * 0.1f + 0.64f * 0.3f, 1e-6);
  // The relit frame: light colour times the blend times alpha.
  const SixWayFrame frame = made_up_six_way_frame();
  const RgbImage relit = relight_six_way(frame, {-1, 1, -1}, {1.0f, 0.5f, 2.0f});
  const float blend = (4.0f + 2.0f + 3.0f) / 8.0f / 3.0f;  // left, top, back
  EXPECT_NEAR(relit.rgb[0], blend * 0.5f, 1e-6);
  EXPECT_NEAR(relit.rgb[1], 0.5f * blend * 0.5f, 1e-6);
  EXPECT_NEAR(relit.rgb[2], 2.0f * blend * 0.5f, 1e-6);
  EXPECT_EQ(relit.rgb[3], 0.0f);
}

TEST(SixWayPasses, EachFacesLightTravelsFromItsSideOfTheCamerasFrame) {
  // A camera on +x looking at the origin: its right is -z, its front (the viewer's side) +x.
  const CameraFrame camera =
      make_camera_frame({4, 0, 0}, {0, 0, 0}, {0, 1, 0}, 40.0f, 0.1f, 100.0f, 8, 8);
  const auto travel = [&](SixWayFace f) { return six_way_face_pass(camera, f).travel; };
  const auto near = [](const glm::vec3& a, const glm::vec3& b) {
    return glm::length(a - b) < 1e-5f;
  };
  EXPECT_TRUE(near(travel(SixWayFace::right), {0, 0, 1}));  // the light at -z travels along +z
  EXPECT_TRUE(near(travel(SixWayFace::top), {0, -1, 0}));
  EXPECT_TRUE(near(travel(SixWayFace::front), {-1, 0, 0}));  // from the viewer into the scene
  EXPECT_TRUE(near(travel(SixWayFace::back), {1, 0, 0}));    // from behind the smoke, at the viewer
  const SixWayPassLight opacity = six_way_opacity_pass();
  EXPECT_EQ(opacity.sun, glm::vec3(0.0f));
  EXPECT_EQ(opacity.ambient, glm::vec3(1.0f));
}

}  // namespace
}  // namespace pyro
