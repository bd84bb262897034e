#pragma once
// The settings a quality target chooses (systems/runtime/quality_picker/quality_picker.h): the particle layer's
// resolution, the footprint table's size, the simulation's time step (as substeps per frame) and,
// in a scene with lit media, how the sun's shadows are found (docs/lighting.md).
#include <optional>

#include <nlohmann/json.hpp>

#include "components/shadow_settings.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

// The shadow method and map of a lit scene; exact_fragments only for the explosions' truth.
struct ShadowChoice {
  ShadowMethod method = ShadowMethod::shadow_map;
  int map_size = 64, map_slices = 32;
  bool exact_fragments = false;

  bool operator==(const ShadowChoice&) const = default;
};

struct QualitySettings {
  float layer_scale = 1.0f;  // 1, 0.5, 0.25, 0.125
  int footprint_size = 64;   // n x n table (Johnson & McAllister 2005, eq. 4)
  int substeps = 1;          // simulation steps per frame: dt = 1 / (fps * substeps)
  std::optional<ShadowChoice> shadows{};  // lit scenes; none: the scene's own (or unlit)

  bool operator==(const QualitySettings&) const = default;
};

// The shadow settings of a lit scene, as a choice.
ShadowChoice shadow_choice(const ShadowSettings& s);

// The scene as it runs with `q`: its layer scale, footprint size and frame rate (fps * substeps,
// so that frame f of the original is frame f * substeps of the result), and when both the scene
// and `q` have shadows, q's method and map.
SceneDescription apply_quality_settings(SceneDescription scene, const QualitySettings& q);

nlohmann::json to_json(const QualitySettings& q);
QualitySettings quality_settings_from_json(const nlohmann::json& j);

}  // namespace pyro
