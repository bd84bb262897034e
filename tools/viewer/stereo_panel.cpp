#include "tools/viewer/stereo_panel.h"

#include <imgui.h>

#include <string>

#include "engine/core/enum_names.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

StereoRequest draw_stereo_panel(StereoMode mode, const nlohmann::json& tree) {
  StereoRequest request;
  const float s = ImGui::GetIO().FontGlobalScale;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // Under the profiler, in the right-hand column the status bar leaves free.
  ImGui::SetNextWindowPos(ImVec2(display.x - 368 * s, 316 * s), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(360 * s, 140 * s), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Stereo")) {
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 11.5f);  // room for "zero_parallax_distance"
    const std::string current(name_of(mode));
    if (ImGui::BeginCombo("mode", current.c_str())) {
      for (const auto& entry : enum_names(mode))
        if (ImGui::Selectable(std::string(entry.name).c_str(), entry.value == mode) && entry.value != mode)
          request.mode = entry.value;
      ImGui::EndCombo();
    }
    draw_scene_keys(stereo_keys(), tree, {"camera", "stereo"}, request.keys);
    ImGui::PopItemWidth();
  }
  ImGui::End();
  return request;
}

}  // namespace pyro
