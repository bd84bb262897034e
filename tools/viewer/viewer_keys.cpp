#include "tools/viewer/viewer_keys.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace pyro {

const std::vector<StereoMode>& stereo_modes_by_key() {
  static const std::vector<StereoMode> modes = {
      StereoMode::mono,           StereoMode::side_by_side,   StereoMode::side_by_side_crossed,
      StereoMode::anaglyph,       StereoMode::anaglyph_color, StereoMode::anaglyph_half_color,
      StereoMode::left_right};
  return modes;
}

namespace {

std::optional<ViewerAction> action_for_control_key(int key, int mods) {
  const bool shift = (mods & GLFW_MOD_SHIFT) != 0;
  if (key == GLFW_KEY_Z) return ViewerAction{shift ? ViewerCommand::redo : ViewerCommand::undo};
  if (key == GLFW_KEY_Y && !shift) return ViewerAction{ViewerCommand::redo};
  if (key == GLFW_KEY_S && !shift) return ViewerAction{ViewerCommand::save};
  return std::nullopt;
}

}  // namespace

std::optional<ViewerAction> action_for_key(int key, int mods) {
  if (mods & (GLFW_MOD_ALT | GLFW_MOD_SUPER)) return std::nullopt;
  if (mods & GLFW_MOD_CONTROL) return action_for_control_key(key, mods);
  if (key >= GLFW_KEY_1 && key <= GLFW_KEY_7)
    return ViewerAction{ViewerCommand::set_stereo, stereo_modes_by_key()[size_t(key - GLFW_KEY_1)]};
  switch (key) {
    case GLFW_KEY_ESCAPE: return ViewerAction{ViewerCommand::quit};
    case GLFW_KEY_TAB: return ViewerAction{ViewerCommand::toggle_camera_mode};
    case GLFW_KEY_B: return ViewerAction{ViewerCommand::toggle_billboards};
    case GLFW_KEY_L: return ViewerAction{ViewerCommand::cycle_layer_scale};
    case GLFW_KEY_SPACE: return ViewerAction{ViewerCommand::toggle_pause};
    case GLFW_KEY_N: return ViewerAction{ViewerCommand::single_step};
    case GLFW_KEY_R: return ViewerAction{ViewerCommand::reload};
    case GLFW_KEY_O: return ViewerAction{ViewerCommand::toggle_overlay};
    case GLFW_KEY_H: return ViewerAction{ViewerCommand::toggle_help};
    default: return std::nullopt;
  }
}

std::optional<int> key_from_name(const std::string& name) {
  std::string n;
  for (char c : name) n += (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c;
  if (n.size() == 1 && n[0] >= '1' && n[0] <= '7') return GLFW_KEY_1 + (n[0] - '1');
  if (n == "B") return GLFW_KEY_B;
  if (n == "L") return GLFW_KEY_L;
  if (n == "N") return GLFW_KEY_N;
  if (n == "R") return GLFW_KEY_R;
  if (n == "O") return GLFW_KEY_O;
  if (n == "H") return GLFW_KEY_H;
  if (n == "SPACE") return GLFW_KEY_SPACE;
  if (n == "TAB") return GLFW_KEY_TAB;
  if (n == "ESC") return GLFW_KEY_ESCAPE;
  return std::nullopt;
}

glm::vec3 move_direction(const HeldKeys& k) {
  return {float(k.right) - float(k.left), float(k.up) - float(k.down),
          float(k.forward) - float(k.back)};
}

float move_speed_factor(const HeldKeys& k) { return k.fast ? 4.0f : 1.0f; }

std::vector<std::string> key_help_lines() {
  return {"DRAG   TURN (ORBIT: ABOUT THE TARGET)",
          "WHEEL  ZOOM / FLY FORWARD",
          "WASD   MOVE, Q/E DOWN/UP, SHIFT FASTER",
          "TAB    ORBIT <-> FLY",
          "1-7    MONO, SIDE-BY-SIDE, CROSSED, ANAGLYPH, COLOR, HALF-COLOR, LEFT-RIGHT",
          "B      BILLBOARDS VIEWPLANE <-> VIEWPOINT",
          "L      LAYER SCALE 1, 1/2, 1/4, 1/8",
          "SPACE  PAUSE, N SINGLE STEP",
          "CTRL+Z UNDO, CTRL+Y REDO, CTRL+S SAVE (THE INSPECTOR'S EDITS)",
          "R      RELOAD, O PANELS, H HELP, ESC QUIT"};
}

std::string key_help_title() {
  return "drag/wheel/WASDQE camera, Tab orbit/fly, 1-7 stereo, B billboards, L layer, "
         "Space pause, N step, Ctrl+Z/Y/S undo/redo/save, R reload, O panels, H help, Esc quit";
}

}  // namespace pyro
