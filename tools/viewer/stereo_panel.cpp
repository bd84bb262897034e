#include "tools/viewer/stereo_panel.h"

#include <imgui.h>

#include <string>

#include "engine/core/enum_names.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

StereoRequest draw_stereo_panel(StereoMode mode, const nlohmann::json& tree, DockedPanel& panel) {
  StereoRequest request;
  const DockedPart part = begin_docked_panel("Stereo", panel);
  if (part == DockedPart::body) {
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 12.5f);  // room for "zero_parallax_distance"
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
  end_docked_panel(part);
  return request;
}

}  // namespace pyro
