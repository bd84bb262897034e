// The viewer's camera controller against its geometry: the starting pose is reproduced, orbit
// turns keep the target and distance, fly turns keep the eye, a full turn comes back, the pitch
// stops short of the poles, moves go along the view's own axes, and switching modes never moves
// the view.
#include "engine/math/view_controller.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

namespace pyro {
namespace {

void expect_near(const glm::vec3& a, const glm::vec3& b, float tol, const char* what) {
  EXPECT_NEAR(a.x, b.x, tol) << what;
  EXPECT_NEAR(a.y, b.y, tol) << what;
  EXPECT_NEAR(a.z, b.z, tol) << what;
}

const CameraPose starts[] = {
    {{0.0f, 3.2f, 15.0f}, {0.0f, 3.0f, 0.0f}, {0.0f, 1.0f, 0.0f}},
    {{3.0f, 2.5f, 7.0f}, {-1.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}},
    {{1.0f, -4.0f, 2.0f}, {0.5f, 0.5f, -1.0f}, {0.0f, 0.0f, 1.0f}},  // z up
};

TEST(ViewController, ReproducesTheStartingPose) {
  for (const CameraPose& s : starts) {
    const ViewController c(s);
    const CameraPose p = c.pose();
    expect_near(p.position, s.position, 1e-4f, "position");
    expect_near(p.target, s.target, 1e-4f, "target");
    expect_near(p.up, glm::normalize(s.up), 1e-6f, "up");
    EXPECT_NEAR(c.distance(), glm::length(s.target - s.position), 1e-5f);
  }
}

TEST(ViewController, OrbitDragKeepsTargetAndDistanceAndAFullTurnComesBack) {
  for (const CameraPose& s : starts) {
    ViewController c(s);
    const float d = glm::length(s.target - s.position);
    c.drag(137.0f, -41.0f);
    const CameraPose p = c.pose();
    expect_near(p.target, s.target, 1e-4f, "target stays");
    EXPECT_NEAR(glm::length(p.position - p.target), d, 1e-4f);
    EXPECT_GT(glm::length(p.position - s.position), 0.1f);  // it did move
    // Back by the same drag: the start again; a full turn in yaw alone: the start too.
    c.drag(-137.0f, 41.0f);
    expect_near(c.pose().position, s.position, 2e-4f, "drag undone");
    const float full_turn_pixels = 6.283185307f / ViewController::turn_per_pixel;
    c.drag(full_turn_pixels, 0.0f);
    expect_near(c.pose().position, s.position, 2e-3f, "full turn");
  }
}

TEST(ViewController, FlyDragKeepsTheEyeAndTurnsRightWhenDraggedRight) {
  ViewController c(starts[0]);
  c.set_mode(CameraControl::fly);
  const glm::vec3 right_before = c.right();
  const glm::vec3 forward_before = c.forward();
  c.drag(40.0f, 0.0f);
  expect_near(c.pose().position, starts[0].position, 1e-5f, "eye stays");
  EXPECT_GT(glm::dot(c.forward(), right_before), 0.0f);
  // A yaw of 40 · turn_per_pixel radians about the up axis (the start view is nearly level).
  const float expected = std::cos(40.0f * ViewController::turn_per_pixel);
  const glm::vec3 level_before = glm::normalize(glm::vec3(forward_before.x, 0, forward_before.z));
  const glm::vec3 level_after = glm::normalize(glm::vec3(c.forward().x, 0, c.forward().z));
  EXPECT_NEAR(glm::dot(level_before, level_after), expected, 1e-5f);
  // Dragging down looks down.
  const float pitch = c.pitch();
  c.drag(0.0f, 10.0f);
  EXPECT_NEAR(c.pitch(), pitch - 10.0f * ViewController::turn_per_pixel, 1e-6f);
}

TEST(ViewController, PitchStopsShortOfThePoles) {
  ViewController c(starts[1]);
  c.drag(0.0f, -1e6f);
  EXPECT_FLOAT_EQ(c.pitch(), ViewController::max_pitch);
  EXPECT_LT(glm::dot(c.forward(), glm::vec3(0, 1, 0)), 1.0f);
  c.drag(0.0f, 1e6f);
  EXPECT_FLOAT_EQ(c.pitch(), -ViewController::max_pitch);
  const CameraPose p = c.pose();
  EXPECT_TRUE(std::isfinite(glm::length(glm::cross(p.target - p.position, p.up))));
  EXPECT_GT(glm::length(glm::cross(glm::normalize(p.target - p.position), p.up)), 0.01f);
}

TEST(ViewController, MovesGoAlongTheViewAxesAtSpeedTimesTime) {
  ViewController c(starts[1]);
  c.set_speed(2.0f);
  const CameraPose before = c.pose();
  const glm::vec3 f = c.forward(), r = c.right();
  c.move({0.0f, 0.0f, 1.0f}, 0.25f);  // forward 0.5
  expect_near(c.pose().position, before.position + 0.5f * f, 1e-5f, "forward");
  expect_near(c.pose().target, before.target + 0.5f * f, 1e-5f, "target moves along");
  c.move({1.0f, 1.0f, 0.0f}, 0.5f);  // right 1 and up 1
  expect_near(c.pose().position, before.position + 0.5f * f + r + glm::vec3(0, 1, 0), 1e-5f, "right+up");
}

TEST(ViewController, WheelZoomsTheOrbitByItsFactorPerStep) {
  ViewController c(starts[0]);
  const float d = c.distance();
  c.scroll(3.0f);
  EXPECT_NEAR(c.distance(), d * std::pow(ViewController::zoom_per_step, 3.0f), 1e-4f);
  expect_near(c.pose().target, starts[0].target, 1e-4f, "target stays");
}

TEST(ViewController, SwitchingModesNeverMovesTheView) {
  ViewController c(starts[1]);
  c.drag(25.0f, 12.0f);
  const CameraPose a = c.pose();
  c.toggle_mode();
  EXPECT_EQ(c.mode(), CameraControl::fly);
  const CameraPose b = c.pose();
  expect_near(b.position, a.position, 0.0f, "position");
  expect_near(b.target, a.target, 0.0f, "target");
  c.toggle_mode();
  EXPECT_EQ(c.mode(), CameraControl::orbit);
}

}  // namespace
}  // namespace pyro
