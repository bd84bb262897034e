// Moving lights: keyframes interpolated against closed forms (the keys themselves at their times,
// a constant angular rate between directions, colour and intensity linear), run by the system at
// the frame clock's time, and read from the scene format with its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "components/frame_clock.h"
#include "engine/ecs/world.h"
#include "systems/lighting/light_animation.h"
#include "systems/runtime/scene/scene_loader.h"

namespace pyro {
namespace {

LightKeyframes two_keys() {
  LightKeyframes k;
  k.keys.push_back({1.0f, {1.0f, 0.0f, 0.0f}, {1.0f, 0.5f, 0.0f}, 2.0f});
  k.keys.push_back({3.0f, {0.0f, -2.0f, 0.0f}, {0.0f, 0.5f, 1.0f}, 0.0f});
  return k;
}

double angle_between(const glm::vec3& a, const glm::vec3& b) {
  return std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0));
}

TEST(LightAnimation, KeysHoldAtTheirTimesAndBeyond) {
  const LightKeyframes k = two_keys();
  for (double t : {0.0, 1.0}) {
    const DirectionalLight l = light_at(k, t);
    EXPECT_NEAR(angle_between(l.direction, {1, 0, 0}), 0.0, 1e-6);
    EXPECT_EQ(l.intensity, 2.0f);
  }
  for (double t : {3.0, 10.0}) EXPECT_NEAR(angle_between(light_at(k, t).direction, {0, -1, 0}), 0.0, 1e-6);
}

TEST(LightAnimation, TurnsAtAConstantRateAndBlendsLinearly) {
  const LightKeyframes k = two_keys();
  for (double f : {0.25, 0.5, 0.8}) {
    const DirectionalLight l = light_at(k, 1.0 + 2.0 * f);
    // 90 degrees from +x to -y: after a fraction f, f * 90 degrees from +x, in the plane of both.
    EXPECT_NEAR(angle_between(l.direction, {1, 0, 0}), f * std::numbers::pi / 2, 1e-6) << f;
    EXPECT_NEAR(l.direction.z, 0.0f, 1e-7);
    EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-6);
    EXPECT_NEAR(l.color.x, 1.0 - f, 1e-6);
    EXPECT_NEAR(l.color.z, f, 1e-6);
    EXPECT_NEAR(l.intensity, 2.0 * (1.0 - f), 1e-6);
  }
}

TEST(LightAnimation, OppositeDirectionsStillTurnThroughAPerpendicular) {
  LightKeyframes k;
  k.keys.push_back({0.0f, {0, -1, 0}, {1, 1, 1}, 1});
  k.keys.push_back({1.0f, {0, 1, 0}, {1, 1, 1}, 1});
  const DirectionalLight l = light_at(k, 0.5);
  EXPECT_NEAR(angle_between(l.direction, {0, -1, 0}), std::numbers::pi / 2, 1e-6);
}

TEST(LightAnimation, TheSystemSetsTheLightAtTheClocksTime) {
  ecs::World world;
  world.set_resource<FrameClock>(FrameClock{60, 1.0f / 30.0f});  // 2 s: halfway between the keys
  const ecs::Entity e = world.create();
  world.emplace<DirectionalLight>(e);
  world.emplace<LightKeyframes>(e, two_keys());
  light_animation_system().run(world);
  EXPECT_NEAR(angle_between(world.get<const DirectionalLight>(e).direction, {1, 0, 0}), std::numbers::pi / 4, 1e-5);
}

TEST(LightAnimation, SceneKeysAreReadInOrderAndRefusedOutOfOrder) {
  const SceneDescription s = parse_scene(R"({"lights": [{"type": "directional", "color": [1, 0.5, 0.2],
      "keys": [{"time": 0, "direction": [1, -1, 0]}, {"time": 4, "direction": [-1, -1, 0], "intensity": 0.2}]}]})",
                                                   "keys.json");
  ASSERT_EQ(s.light_keyframes.size(), 1u);
  ASSERT_EQ(s.light_keyframes[0].keys.size(), 2u);
  EXPECT_EQ(s.light_keyframes[0].keys[1].color, glm::vec3(1, 0.5f, 0.2f));  // the light's own colour
  EXPECT_EQ(s.light_keyframes[0].keys[1].intensity, 0.2f);
  EXPECT_EQ(s.directional_lights[0].direction, glm::vec3(1, -1, 0));  // the first key's
  try {
    parse_scene(R"({"lights": [{"type": "directional",
        "keys": [{"time": 2}, {"time": 1}]}]})", "bad.json");
    FAIL() << "keys out of order were accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("/lights/0/keys/1/time"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pyro
