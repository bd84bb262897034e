#pragma once
// The stereo panel (Dear ImGui): the output's stereo mode (a viewer setting, as the number keys
// choose it) and the scene's stereo pair (camera.stereo: interocular, zero-parallax distance,
// eye order), edited like any other key through the scene document.
#include <optional>

#include <nlohmann/json.hpp>

#include "components/render_settings.h"
#include "tools/viewer/docked_panel.h"
#include "tools/viewer/inspector_panel.h"

namespace pyro {

struct StereoRequest {
  std::optional<StereoMode> mode;
  InspectorRequest keys;  // an edit of camera.stereo
};

StereoRequest draw_stereo_panel(StereoMode mode, const nlohmann::json& tree, DockedPanel& panel);

}  // namespace pyro
