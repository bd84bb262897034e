#pragma once
// The window's side of the viewer's image: the runtime's output (sRGB bytes already) copied into
// its place in the window's default framebuffer (beside the panels: panel_layout.h), as bytes;
// and the window's image read back for a screenshot.
#include <cstdint>
#include <vector>

#include "engine/gpu/render_target.h"
#include "tools/viewer/panel_layout.h"

namespace pyro {

// While it lives, writes are bytes as given: GL_FRAMEBUFFER_SRGB off (the runtime's passes work
// in linear light with it on, and get it back when the scope ends).
class SrgbWritesOff {
 public:
  SrgbWritesOff();
  ~SrgbWritesOff();
  SrgbWritesOff(const SrgbWritesOff&) = delete;
  SrgbWritesOff& operator=(const SrgbWritesOff&) = delete;
};

// Inside an SrgbWritesOff scope: clears the default framebuffer (window_width x window_height)
// to dark grey and blits `output` into `place` (window pixels, y down: panel_layout.h's
// fit_frame), nearest when the sizes match, else linear.
void present_frame(const gpu::RenderTarget& output, const PanelRect& place, int window_width,
                   int window_height);

// The default framebuffer's back buffer as RGB8, row 0 at the top.
std::vector<uint8_t> read_window_rgb(int width, int height);

}  // namespace pyro
