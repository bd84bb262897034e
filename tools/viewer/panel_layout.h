#pragma once
// Where pyro view draws, window-free: the scene's frame on the left and the panels stacked in a
// column along the window's right edge, each panel a header (collapsed) or a header and its
// body (expanded). Worked out again every frame from the window's size, so that at any size no
// panel lies off the window, over another panel or over the frame.
#include <vector>

namespace pyro {

// A rectangle in window pixels, y down from the top left corner.
struct PanelRect {
  float x = 0, y = 0, width = 0, height = 0;
  bool operator==(const PanelRect&) const = default;
};

// The width of the panel column at a widget scale (1: 13-pixel text).
float panel_column_width(float scale);

struct WindowSize {
  int width = 0, height = 0;
  bool operator==(const WindowSize&) const = default;
};

// The size the window opens at for a frame of frame_width x frame_height. With a panel column
// (column_width > 0): the frame's area beside the column, at least as wide as the column and at
// least 240 pixels high (room for the column's headers); without: the frame's size.
WindowSize viewer_window_size(int frame_width, int frame_height, float column_width);

// The window's two parts: the column along the right edge, column_width wide but never more
// than half the window, and the rest, where the frame goes.
struct WindowSplit {
  PanelRect view, column;
};
WindowSplit split_window(float window_width, float window_height, float column_width);

// Where a frame_width x frame_height frame lies in `area`: scaled to fit, centred, in whole
// pixels (its own size when the area holds it exactly).
PanelRect fit_frame(const PanelRect& area, int frame_width, int frame_height);

// One panel of the column: its height collapsed (its header) and the height it would like
// expanded (header and body).
struct ColumnPanel {
  float header = 0;
  float wanted = 0;
  bool expanded = false;
};

// The panels top to bottom in `column`, `gap` apart: collapsed ones as their headers; expanded
// ones share the height the headers leave, each up to its wanted height. When their bodies do not
// all fit, the shares are fair: from the smallest body up, each gets what it wants or an equal
// share of what is left, whichever is less (so a short panel is whole before a long one grows).
// Every rectangle lies inside the column, below the one before it, in whole pixels.
std::vector<PanelRect> stack_panels(const PanelRect& column, const std::vector<ColumnPanel>& panels,
                                    float gap);

}  // namespace pyro
