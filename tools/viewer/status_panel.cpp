#include "tools/viewer/status_panel.h"

#include <imgui.h>

namespace pyro {

void draw_status_panel(const std::vector<OverlayLine>& lines) {
  const ImGuiIO& io = ImGui::GetIO();
  const float s = io.FontGlobalScale;
  ImGui::SetNextWindowPos(ImVec2(8 * s, io.DisplaySize.y - 8 * s), ImGuiCond_Always, ImVec2(0, 1));
  // Left of the profiler's and stereo panel's column when the window is wide enough for both.
  const float column = io.DisplaySize.x > 900 * s ? 376 * s : 0.0f;
  const float width = io.DisplaySize.x - 16 * s - column;
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(width, io.DisplaySize.y * 0.5f));
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("Status", nullptr, flags)) {
    ImGui::PushTextWrapPos(width - 16 * s);
    for (const OverlayLine& line : lines) {
      if (line.error) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
      ImGui::TextUnformatted(line.text.c_str());
      if (line.error) ImGui::PopStyleColor();
    }
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

}  // namespace pyro
