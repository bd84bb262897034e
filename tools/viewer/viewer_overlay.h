#pragma once
// The text pyro view draws over the scene, laid out in lines of at most `columns` characters:
// frame rate, frame number, particle count and what the keys have chosen; the per-system
// milliseconds; the reload error while the last edit is broken; the keys when help is on.
#include <string>
#include <utility>
#include <vector>

namespace pyro {

struct OverlayInfo {
  std::string scene;  // the scene file
  double fps = 0.0;
  double frame_ms = 0.0;
  unsigned long long frame = 0;
  size_t particles = 0;
  std::vector<std::pair<std::string, double>> system_ms;  // name, milliseconds (mean)
  std::string stereo, billboards, layer_scale, camera;
  bool paused = false;
  std::string error;  // non-empty: the last reload failed
  bool help = false;
};

struct OverlayLine {
  std::string text;
  bool error = false;  // drawn in the error colour
};

// Splits `text` into lines of at most `columns` characters, breaking at spaces where it can and
// inside words longer than a line; newlines in `text` always break. columns >= 1.
std::vector<std::string> wrap_text(const std::string& text, int columns);

std::vector<OverlayLine> overlay_lines(const OverlayInfo& info, int columns);

// One line for the status panel's header, seen while the panel is collapsed: "Status  30.0 fps
// frame 12" (and "  PAUSED").
std::string overlay_header(const OverlayInfo& info);

}  // namespace pyro
