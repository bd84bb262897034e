#pragma once
// pyro view's keys: what each key press does (viewer_settings.h applies it), the held keys that
// fly the camera, and the help text the window title and the overlay show.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "components/render_settings.h"

namespace pyro {

enum class ViewerCommand {
  quit,                // Esc
  toggle_camera_mode,  // Tab: orbit <-> fly
  set_stereo,          // 1..7 (ViewerAction::stereo says which)
  toggle_billboards,   // B: viewplane <-> viewpoint
  cycle_layer_scale,   // L: 1 -> 1/2 -> 1/4 -> 1/8 -> 1
  toggle_pause,        // Space
  single_step,         // N: one simulation step (pauses)
  reload,              // R: load the scene file again now
  toggle_overlay,      // O
  toggle_help,         // H
  undo,                // Ctrl+Z: the inspector's last edit
  redo,                // Ctrl+Y or Ctrl+Shift+Z
  save,                // Ctrl+S: the edited scene over its file
};

struct ViewerAction {
  ViewerCommand command = ViewerCommand::quit;
  StereoMode stereo = StereoMode::mono;  // for set_stereo
  bool operator==(const ViewerAction&) const = default;
};

// The stereo mode of keys 1..7, in this order: mono, side-by-side, side-by-side-crossed,
// anaglyph, anaglyph-color, anaglyph-half-color, left-right.
const std::vector<StereoMode>& stereo_modes_by_key();

// The action of a key press (GLFW_KEY_* and GLFW_MOD_*), or none for keys without one
// (the fly keys act while held, not on presses). With Ctrl: Z, Y and S only.
std::optional<ViewerAction> action_for_key(int key, int mods);

// A key by the name the README and --press-at use: "1".."7", "B", "L", "N", "R", "O", "H",
// "SPACE", "TAB", "ESC" (any case); none for other names.
std::optional<int> key_from_name(const std::string& name);

// Which fly keys are held. move_direction(): x right (D − A), y up (E − Q), z forward (W − S);
// each component −1, 0 or 1.
struct HeldKeys {
  bool forward = false, back = false, left = false, right = false, up = false, down = false;
  bool fast = false;  // Shift: 4× speed
};
glm::vec3 move_direction(const HeldKeys& keys);
float move_speed_factor(const HeldKeys& keys);

// One line per key, e.g. "TAB  ORBIT <-> FLY", for the overlay's help and the README.
std::vector<std::string> key_help_lines();
// A short form for the window title.
std::string key_help_title();

}  // namespace pyro
