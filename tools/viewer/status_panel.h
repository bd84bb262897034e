#pragma once
// The status panel (Dear ImGui): the lines viewer_overlay.h composes (rates, frame, particles,
// the modes the keys chose, per-system milliseconds, a failed reload's message in red, the keys
// when help is on), at the bottom left of the window.
#include <vector>

#include "tools/viewer/viewer_overlay.h"

namespace pyro {

void draw_status_panel(const std::vector<OverlayLine>& lines);

}  // namespace pyro
