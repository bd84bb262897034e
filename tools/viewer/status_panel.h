#pragma once
// The status panel (Dear ImGui), first in the panel column: its header carries the frame rate
// and frame; its body the lines viewer_overlay.h composes (rates, frame, particles, the modes
// the keys chose, per-system milliseconds, a failed reload's message in red, the keys when help
// is on), wrapped to the column's width.
#include <string>
#include <vector>

#include "tools/viewer/docked_panel.h"
#include "tools/viewer/viewer_overlay.h"

namespace pyro {

// Characters per line of the body in a panel `width` pixels wide (at least 1).
int status_panel_columns(float width);

// The height the panel would like expanded, for `lines` lines of body.
float status_panel_height(size_t lines);

void draw_status_panel(const std::string& header, const std::vector<OverlayLine>& lines,
                       DockedPanel& panel);

}  // namespace pyro
