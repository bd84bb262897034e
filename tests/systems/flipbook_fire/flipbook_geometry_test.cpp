// Flipbook fire geometry (Rose 2007, section 4.6): the group turns about the base normal to face
// the viewer, billboards stay perpendicular to the base, and in stereo both eyes get the one
// group that faces the mid-eye point.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "systems/camera/camera_views.h"
#include "systems/flipbook_fire/flipbook_geometry.h"
#include "systems/flipbook_fire/flipbook_layout.h"

namespace pyro {
namespace {

FlipbookFire pairs_fire(const glm::vec3& position, const glm::vec3& up) {
  FlipbookFire fire;
  fire.position = position;
  fire.up = up;
  fire.width = 0.3f;
  fire.aspect = 1.5f;
  fire.groups.emplace_back();
  fire.billboards = expand_flipbook_groups(fire);
  return fire;
}

TEST(FlipbookGeometry, BillboardsStandOnTheBaseAndFaceTheViewer) {
  for (const glm::vec3 up : {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(0.3f, 1.0f, -0.2f))}) {
    for (const glm::vec3 viewer : {glm::vec3(0, 1.5f, 8), glm::vec3(-5, 3, 1), glm::vec3(2, -1, -3)}) {
      const glm::vec3 base{1.0f, 0.5f, -2.0f};
      const FlipbookFire fire = pairs_fire(base, up);
      const FireFrame frame = face_viewer(base, up, viewer, {0, 0, 1});
      // The depth axis is the viewer's direction with its component along up removed.
      glm::vec3 d = viewer - base;
      d -= up * glm::dot(d, up);
      EXPECT_NEAR(glm::dot(frame.toward, glm::normalize(d)), 1.0f, 1e-5f);
      const auto quads = flipbook_quads(fire, frame, 0, 32);
      ASSERT_EQ(quads.size(), 6u);
      for (const FlipbookQuad& q : quads) {
        const glm::vec3 side = q.corners[1] - q.corners[0];
        const glm::vec3 rise = q.corners[2] - q.corners[0];
        // Perpendicular to the base: the billboard's vertical edge is the base normal, its
        // bottom edge lies in the base plane (the thesis' 1:1.5 aspect).
        EXPECT_NEAR(glm::length(glm::cross(rise, up)), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::length(rise), 0.45f, 1e-5f);
        EXPECT_NEAR(glm::dot(side, up), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::length(side), 0.3f, 1e-5f);
        EXPECT_NEAR(glm::dot(q.corners[0] - base, up), 0.0f, 1e-5f);
        // Facing the viewer: the normal is the depth axis; corner 1 is to the viewer's right.
        const glm::vec3 normal = glm::normalize(glm::cross(side, rise));
        EXPECT_NEAR(glm::dot(normal, frame.toward), 1.0f, 1e-5f);
      }
      // Back to front.
      for (size_t k = 1; k < quads.size(); ++k) EXPECT_LE(quads[k - 1].depth, quads[k].depth);
    }
  }
}

TEST(FlipbookGeometry, ViewerOnTheAxisUsesTheFallback) {
  const FireFrame f = face_viewer({0, 0, 0}, {0, 1, 0}, {0, 5, 0}, {1, 0, 0});
  EXPECT_NEAR(glm::dot(f.toward, glm::vec3(1, 0, 0)), 1.0f, 1e-6f);
  const FireFrame g = face_viewer({0, 0, 0}, {0, 1, 0}, {0, 5, 0}, {0, 1, 0});
  EXPECT_NEAR(glm::dot(g.toward, glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(g.toward), 1.0f, 1e-6f);
}

TEST(FlipbookGeometry, StereoEyesShareTheMidEyeGroup) {
  // A fire off to the side: each eye facing for itself would turn the group differently.
  Camera camera;
  camera.position = {0.0f, 1.0f, 3.0f};
  camera.target = {0.0f, 0.4f, 0.0f};
  RenderSettings settings;
  settings.stereo_mode = StereoMode::side_by_side;
  StereoCamera stereo;
  stereo.parameters.interocular = 0.5f;
  const std::vector<CameraFrame> eyes = rendered_views(camera, &stereo, settings);
  const CameraFrame mid = mono_frame(camera, settings);
  ASSERT_EQ(eyes.size(), 2u);
  const glm::vec3 base{1.2f, 0.0f, -0.5f};
  const FireFrame from_mid = face_viewer(base, {0, 1, 0}, mid.eye, -mid.forward);
  const FireFrame from_left = face_viewer(base, {0, 1, 0}, eyes[0].eye, -mid.forward);
  const FireFrame from_right = face_viewer(base, {0, 1, 0}, eyes[1].eye, -mid.forward);
  // The mid-eye is the midpoint of the eyes, so its facing direction lies strictly between
  // theirs; the system uses it for both eyes (flipbook_render_system.cpp, View::frame).
  EXPECT_NEAR(glm::length(0.5f * (eyes[0].eye + eyes[1].eye) - mid.eye), 0.0f, 1e-5f);
  const float a_left = std::acos(std::min(1.0f, glm::dot(from_mid.toward, from_left.toward)));
  const float a_right = std::acos(std::min(1.0f, glm::dot(from_mid.toward, from_right.toward)));
  EXPECT_GT(a_left, 0.02f);
  EXPECT_GT(a_right, 0.02f);
  EXPECT_NEAR(a_left, a_right, 0.1f * a_left);
}

}  // namespace
}  // namespace pyro
