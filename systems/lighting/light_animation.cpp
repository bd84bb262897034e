#include "systems/lighting/light_animation.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "components/frame_clock.h"
#include "engine/ecs/world.h"

namespace pyro {

namespace {

// Spherical linear interpolation of unit vectors a and b (Shoemake 1985).
glm::dvec3 slerp(const glm::dvec3& a, const glm::dvec3& b, double t) {
  const double cosine = std::clamp(glm::dot(a, b), -1.0, 1.0);
  const double angle = std::acos(cosine);
  if (angle < 1e-9) return a;
  glm::dvec3 toward = b - cosine * a;  // b's part perpendicular to a
  if (glm::length(toward) < 1e-12) {   // opposite: any axis perpendicular to a
    toward = glm::cross(a, std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
  }
  toward = glm::normalize(toward);
  return std::cos(angle * t) * a + std::sin(angle * t) * toward;
}

DirectionalLight from_key(const LightKeyframe& k) { return {k.direction, k.color, k.intensity}; }

}  // namespace

DirectionalLight light_at(const LightKeyframes& lights, double time) {
  const std::vector<LightKeyframe>& keys = lights.keys;
  if (keys.empty()) return {};
  if (time <= keys.front().time) return from_key(keys.front());
  if (time >= keys.back().time) return from_key(keys.back());
  const auto next = std::upper_bound(keys.begin(), keys.end(), time,
                                     [](double t, const LightKeyframe& k) { return t < k.time; });
  const LightKeyframe& a = *(next - 1);
  const LightKeyframe& b = *next;
  const double t = (time - a.time) / (b.time - a.time);
  DirectionalLight light;
  const glm::dvec3 da = glm::normalize(glm::dvec3(a.direction)), db = glm::normalize(glm::dvec3(b.direction));
  light.direction = glm::vec3(slerp(da, db, t));
  light.color = glm::vec3(glm::mix(glm::dvec3(a.color), glm::dvec3(b.color), t));
  light.intensity = float(a.intensity + (b.intensity - a.intensity) * t);
  return light;
}

ecs::SystemDesc light_animation_system() {
  return {.name = "light_animation",
          .phase = ecs::Phase::simulate,
          .access = ecs::Access::of<ecs::Reads<LightKeyframes, FrameClock>, ecs::Writes<DirectionalLight>>(),
          .run = [](ecs::World& world) {
            const FrameClock* clock = world.try_resource<const FrameClock>();
            const double time = clock ? clock->time() : 0.0;
            world.each<const LightKeyframes, DirectionalLight>(
                [&](const LightKeyframes& keys, DirectionalLight& light) { light = light_at(keys, time); });
          }};
}

}  // namespace pyro
