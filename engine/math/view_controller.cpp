#include "engine/math/view_controller.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace pyro {

ViewController::ViewController(const CameraPose& start) {
  up_ = glm::normalize(start.up);
  const glm::vec3 to_target = start.target - start.position;
  distance_ = glm::length(to_target);
  const glm::vec3 f = to_target / distance_;
  // A horizontal reference direction: the view's own when it has one, else any axis ⟂ up.
  glm::vec3 h = f - up_ * glm::dot(f, up_);
  if (glm::length(h) < 1e-6f) {
    h = std::abs(up_.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    h -= up_ * glm::dot(h, up_);
  }
  e1_ = glm::normalize(h);
  e2_ = glm::cross(e1_, up_);
  yaw_ = 0.0f;
  pitch_ = std::clamp(std::asin(std::clamp(glm::dot(f, up_), -1.0f, 1.0f)), -max_pitch, max_pitch);
  // Keep the target where it was: the eye moves only if the pitch had to be clamped.
  position_ = start.target - distance_ * forward();
  speed_ = std::max(distance_ * 0.5f, 1e-3f);
}

glm::vec3 ViewController::forward() const {
  return std::cos(pitch_) * (std::cos(yaw_) * e1_ + std::sin(yaw_) * e2_) + std::sin(pitch_) * up_;
}

glm::vec3 ViewController::right() const { return glm::normalize(glm::cross(forward(), up_)); }

CameraPose ViewController::pose() const {
  return {position_, position_ + distance_ * forward(), up_};
}

void ViewController::drag(float dx_pixels, float dy_pixels) {
  const glm::vec3 target = position_ + distance_ * forward();
  yaw_ = std::remainder(yaw_ + dx_pixels * turn_per_pixel, 6.283185307f);
  pitch_ = std::clamp(pitch_ - dy_pixels * turn_per_pixel, -max_pitch, max_pitch);
  if (mode_ == CameraControl::orbit) position_ = target - distance_ * forward();
}

void ViewController::scroll(float steps) {
  if (mode_ == CameraControl::orbit) {
    const glm::vec3 target = position_ + distance_ * forward();
    distance_ = std::max(distance_ * std::pow(zoom_per_step, steps), 1e-3f);
    position_ = target - distance_ * forward();
  } else {
    position_ += forward() * (steps * speed_ * 0.1f);
  }
}

void ViewController::move(const glm::vec3& local, float dt) {
  const glm::vec3 f = forward();
  const glm::vec3 r = glm::normalize(glm::cross(f, up_));
  position_ += (r * local.x + up_ * local.y + f * local.z) * (speed_ * dt);
}

}  // namespace pyro
