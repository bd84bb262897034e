#pragma once
// The settings a quality target chooses (systems/quality_picker/quality_picker.h): the particle layer's
// resolution, the footprint table's size and the simulation's time step (as substeps per frame).
#include <nlohmann/json.hpp>

#include "systems/scene/scene_description.h"

namespace pyro {

struct QualitySettings {
  float layer_scale = 1.0f;  // 1, 0.5, 0.25, 0.125
  int footprint_size = 64;   // n x n table (Johnson & McAllister 2005, eq. 4)
  int substeps = 1;          // simulation steps per frame: dt = 1 / (fps * substeps)
};

// The scene as it runs with `q`: its layer scale, footprint size and frame rate (fps * substeps,
// so that frame f of the original is frame f * substeps of the result).
SceneDescription apply_quality_settings(SceneDescription scene, const QualitySettings& q);

nlohmann::json to_json(const QualitySettings& q);
QualitySettings quality_settings_from_json(const nlohmann::json& j);

}  // namespace pyro
