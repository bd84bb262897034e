#pragma once
// A panel of the viewer's column (Dear ImGui): a window at the rectangle the layout gave it
// (panel_layout.h), which the mouse neither moves nor resizes, whose first line is a header that
// expands and collapses it. The header's state is the caller's `expanded`, changed at the click,
// so the next frame's layout has it. While expanded, the body under the header scrolls on its own.
//
//   const DockedPart part = begin_docked_panel("Profiler", panel);
//   if (part == DockedPart::body) { ...the body's widgets... }
//   end_docked_panel(part);
#include <string>

#include "tools/viewer/panel_layout.h"

namespace pyro {

struct DockedPanel {
  PanelRect rect;         // where it is drawn this frame
  bool expanded = false;  // the header's state
};

// What begin_docked_panel() began: nothing (no room in the window for the panel), the window
// with its header, or the window with its header and body.
enum class DockedPart { none, header, body };

// Begins the window `name` at panel.rect with its header (labelled `header`, or `name` when
// empty); its body too when expanded. Call end_docked_panel() with what it returned.
DockedPart begin_docked_panel(const char* name, DockedPanel& panel, const std::string& header = {});
void end_docked_panel(DockedPart part);

// The height of a collapsed panel (its header and the window's padding) and the padding, after
// the current frame's style and font.
float docked_panel_header_height();
float docked_panel_padding();

}  // namespace pyro
