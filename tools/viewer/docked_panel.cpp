#include "tools/viewer/docked_panel.h"

#include <imgui.h>

#include <cmath>

namespace pyro {

float docked_panel_padding() { return std::round(4.0f * ImGui::GetIO().FontGlobalScale); }

float docked_panel_header_height() {
  return std::ceil(ImGui::GetFrameHeight() + 2 * docked_panel_padding());
}

DockedPart begin_docked_panel(const char* name, DockedPanel& panel, const std::string& header) {
  if (panel.rect.width < 1 || panel.rect.height < 1) return DockedPart::none;
  const float pad = docked_panel_padding();
  ImGui::SetNextWindowPos(ImVec2(panel.rect.x, panel.rect.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(panel.rect.width, panel.rect.height), ImGuiCond_Always);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(pad, pad));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse |
                                 ImGuiWindowFlags_NoSavedSettings;
  const bool visible = ImGui::Begin(name, nullptr, flags);
  ImGui::PopStyleVar(2);
  if (!visible) return DockedPart::header;
  // "###" keeps the header's identity when its label changes (the status's rates).
  const std::string label = (header.empty() ? std::string(name) : header) + "###header";
  ImGui::SetNextItemOpen(panel.expanded, ImGuiCond_Always);
  panel.expanded = ImGui::CollapsingHeader(label.c_str());
  if (!panel.expanded) return DockedPart::header;
  ImGui::BeginChild("body");
  return DockedPart::body;
}

void end_docked_panel(DockedPart part) {
  if (part == DockedPart::body) ImGui::EndChild();
  if (part != DockedPart::none) ImGui::End();
}

}  // namespace pyro
