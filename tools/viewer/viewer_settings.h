#pragma once
// What pyro view shows and how, as the keys change it: stereo mode, billboard alignment, layer
// scale (these three need a new runtime), pause and single steps, the overlay and its help.
#include <string>
#include <string_view>

#include "components/render_settings.h"
#include "systems/runtime/scene/scene_description.h"
#include "tools/viewer/viewer_keys.h"

namespace pyro {

struct ViewerSettings {
  StereoMode stereo = StereoMode::mono;
  BillboardAlignment billboards = BillboardAlignment::viewplane;
  float layer_scale = 1.0f;
  bool paused = false;
  int pending_steps = 0;  // single steps asked for while paused, not yet run
  bool overlay = true;
  bool help = false;
};

// What the viewer must do after an action beyond the settings' own change.
struct ViewerEffect {
  bool rebuild_runtime = false;  // stereo, billboards or layer scale changed
  bool reload_scene = false;
  bool quit = false;
  bool toggle_camera_mode = false;
  bool undo = false, redo = false, save = false;  // the scene document's (the inspector's edits)
};

// 1 -> 1/2 -> 1/4 -> 1/8 -> 1; any other value goes to 1.
float next_layer_scale(float scale);

ViewerEffect apply_action(ViewerSettings& settings, const ViewerAction& action);

// "1/2" for 0.5, "1" for 1.
const char* layer_scale_name(float scale);
// The overlay's font has capitals only: "side-by-side" -> "SIDE-BY-SIDE" (names from the enums'
// tables, engine/core/enum_names.h).
std::string upper_case(std::string_view name);

}  // namespace pyro
