#pragma once
// The interactive viewer (pyro view): a GLFW window (engine/gpu/window_context.h) whose context
// the scene runtime renders with; each frame the runtime's output is drawn into the window
// (window_image.h) beside the panels' column (panel_layout.h, panel_column.h). The logic lives in window-free files with
// their own tests: the keys (viewer_keys.h), what they change (viewer_settings.h), the camera
// (engine/math/view_controller.h), hot reload (scene_reloader.h) and the overlay's text
// (viewer_overlay.h); this module and engine_window are the only code that links GLFW.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

// At `frame`, `content` is written over the scene file in place, as an editor saving would; the
// hot reload then finds the edit like any other.
struct ViewerEdit {
  uint64_t frame = 0;
  std::string content;
};

// At `frame`, `key` (GLFW_KEY_*) is pressed, through the same path as a real press.
struct ViewerPress {
  uint64_t frame = 0;
  int key = 0;
};

// At `frame`, the value at `pointer` is set through the scene document, as the inspector sets it.
struct ViewerSet {
  uint64_t frame = 0;
  std::string pointer;
  nlohmann::json value;
};

// At `frame`, the window's image is written to `file` (PNG).
struct ViewerScreenshot {
  uint64_t frame = 0;
  std::string file;
};

struct ViewerOptions {
  std::string scene;           // the file shown and watched
  int width = 0, height = 0;   // view size; 0: the scene's
  int frames = 0;              // 0: until the window is closed
  std::string screenshot;      // PNG of the window after the last frame (or when closed)
  bool overlay = true;         // the panels (status, inspector, profiler, stereo)
  std::string inspect;         // a JSON pointer the inspector opens at, e.g. "/clouds/0"
  std::vector<std::string> expand;  // panels that start expanded: status, inspector, profiler, stereo
  RuntimeOptions runtime;      // stereo mode, billboards, layer scale: the keys change them later
  std::vector<ViewerEdit> edits;
  std::vector<ViewerPress> presses;
  // Scripted authoring (tests, automation): sets, then undos, at their frames, before the frame's
  // step; a set or undo the document refuses ends the session with the loader's message (a
  // UserError) and nothing saved. After the last frame the document is saved to `save_as`.
  std::vector<ViewerSet> sets;
  std::vector<uint64_t> undos;
  std::vector<ViewerScreenshot> screenshots;
  std::string save_as;
  NoteSink on_note;            // reloads, good and failed
};

// Opens the window (GpuError when there is no display or no OpenGL 4.5 context), shows `scene`
// until the window closes, Esc, or options.frames frames, and returns the summary: frames, fps,
// milliseconds per frame (runtime and window parts), the settings at the end, the reloads, the
// edits applied, what the assets cost (files read or reused, flipbooks baked), and the quality
// pick it runs with (a scene with quality.max_rmse, opened as every command opens it:
// systems/runtime/open_scene/open_scene.h).
nlohmann::json run_viewer(const ViewerOptions& options, SceneDescription scene);

}  // namespace pyro
