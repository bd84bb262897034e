#include "systems/runtime/quality/quality_settings.h"

#include <stdexcept>
#include <string>

#include "engine/core/enum_names.h"

namespace pyro {

ShadowChoice shadow_choice(const ShadowSettings& s) {
  return {s.method, s.map_size, s.map_slices, s.exact_fragments};
}

SceneDescription apply_quality_settings(SceneDescription scene, const QualitySettings& q) {
  scene.render.layer_scale = q.layer_scale;
  scene.footprint.size = q.footprint_size;
  scene.frames_per_second *= static_cast<float>(q.substeps);
  if (q.shadows && scene.shadows) {
    scene.shadows->method = q.shadows->method;
    scene.shadows->map_size = q.shadows->map_size;
    scene.shadows->map_slices = q.shadows->map_slices;
    scene.shadows->exact_fragments = q.shadows->exact_fragments;
  }
  return scene;
}

nlohmann::json to_json(const QualitySettings& q) {
  nlohmann::json j = {{"layer_scale", q.layer_scale}, {"footprint_size", q.footprint_size}, {"substeps", q.substeps}};
  if (q.shadows)
    j["shadows"] = {{"method", std::string(name_of(q.shadows->method))},
                    {"map_size", q.shadows->map_size},
                    {"map_slices", q.shadows->map_slices}};
  return j;
}

QualitySettings quality_settings_from_json(const nlohmann::json& j) {
  QualitySettings q;
  q.layer_scale = j.at("layer_scale").get<float>();
  q.footprint_size = j.at("footprint_size").get<int>();
  q.substeps = j.at("substeps").get<int>();
  if (j.contains("shadows")) {
    const nlohmann::json& s = j.at("shadows");
    const std::optional<ShadowMethod> method = enum_from_name<ShadowMethod>(s.at("method").get<std::string>());
    if (!method) throw std::runtime_error("an unknown shadow method " + s.at("method").dump());
    q.shadows = ShadowChoice{*method, s.at("map_size").get<int>(), s.at("map_slices").get<int>(), false};
  }
  return q;
}

}  // namespace pyro
