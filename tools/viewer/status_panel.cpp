#include "tools/viewer/status_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace pyro {

int status_panel_columns(float width) {
  // The body's width: the window's padding and the child's, and room for a scroll bar.
  const float text = width - 4 * docked_panel_padding() - ImGui::GetStyle().ScrollbarSize;
  return std::max(1, int(text / ImGui::CalcTextSize("M").x));
}

float status_panel_height(size_t lines) {
  const float body =
      float(lines) * ImGui::GetTextLineHeightWithSpacing() + ImGui::GetStyle().ItemSpacing.y;
  return std::ceil(docked_panel_header_height() + body);
}

void draw_status_panel(const std::string& header, const std::vector<OverlayLine>& lines,
                       DockedPanel& panel) {
  const DockedPart part = begin_docked_panel("Status", panel, header);
  if (part == DockedPart::body) {
    for (const OverlayLine& line : lines) {
      if (line.error) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
      ImGui::TextUnformatted(line.text.c_str());
      if (line.error) ImGui::PopStyleColor();
    }
  }
  end_docked_panel(part);
}

}  // namespace pyro
