#pragma once
// The viewer's camera controller (pyro view): orbit about a target or fly freely, driven by
// mouse drags, the wheel and held keys. One state serves both modes — the eye position, the
// view direction as yaw and pitch about the scene's up axis, and the distance to the orbit
// target (target = position + distance · forward) — so switching modes never moves the view.
//   orbit: dragging turns the view about the target (the target and distance stay fixed), the
//          wheel moves towards or away from the target, keys pan eye and target together;
//   fly:   dragging turns the view about the eye, the wheel and keys move the eye and the
//          target together.
#include <glm/vec3.hpp>

#include "engine/core/enum_names.h"

namespace pyro {

struct CameraPose {
  glm::vec3 position{0.0f};
  glm::vec3 target{0.0f, 0.0f, -1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
};

enum class CameraControl { orbit, fly };
inline constexpr EnumName<CameraControl> camera_control_names[] = {{CameraControl::orbit, "orbit"},
                                                                {CameraControl::fly, "fly"}};
constexpr const auto& enum_names(CameraControl) { return camera_control_names; }

class ViewController {
 public:
  // Radians of turn per pixel dragged; the pitch stays within ±max_pitch of the horizon.
  static constexpr float turn_per_pixel = 0.005f;
  static constexpr float max_pitch = 1.5533430f;  // 89 degrees
  static constexpr float zoom_per_step = 0.9f;     // orbit distance factor per wheel step

  // `start.up` is the axis yaw turns about (normalised here); position ≠ target.
  explicit ViewController(const CameraPose& start);

  CameraControl mode() const { return mode_; }
  void set_mode(CameraControl mode) { mode_ = mode; }
  void toggle_mode() { mode_ = mode_ == CameraControl::orbit ? CameraControl::fly : CameraControl::orbit; }

  // A drag of (dx, dy) pixels, x right, y down: right turns the view right (in orbit mode the
  // eye circles left about the target), down turns it down (the eye rises over the target).
  void drag(float dx_pixels, float dy_pixels);
  // Wheel steps, positive towards the scene: orbit scales the distance by zoom_per_step^steps;
  // fly moves eye and target forward by steps · speed · 0.1 s.
  void scroll(float steps);
  // Moves eye and target by `local` (x right, y up, z forward; unit-free, typically each -1, 0 or
  // 1) · speed · dt.
  void move(const glm::vec3& local, float dt);

  void set_speed(float units_per_second) { speed_ = units_per_second; }
  float speed() const { return speed_; }
  float distance() const { return distance_; }
  float yaw() const { return yaw_; }
  float pitch() const { return pitch_; }

  glm::vec3 forward() const;
  glm::vec3 right() const;
  CameraPose pose() const;

 private:
  CameraControl mode_ = CameraControl::orbit;
  glm::vec3 up_, e1_, e2_;  // e1 = forward at yaw 0, e2 = cross(e1, up): yaw turns right
  glm::vec3 position_;
  float yaw_ = 0.0f, pitch_ = 0.0f, distance_ = 1.0f;
  float speed_ = 1.0f;
};

}  // namespace pyro
