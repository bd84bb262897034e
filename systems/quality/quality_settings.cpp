#include "systems/quality/quality_settings.h"

namespace pyro {

SceneDescription apply_quality_settings(SceneDescription scene, const QualitySettings& q) {
  scene.render.layer_scale = q.layer_scale;
  scene.footprint.size = q.footprint_size;
  scene.frames_per_second *= static_cast<float>(q.substeps);
  return scene;
}

nlohmann::json to_json(const QualitySettings& q) {
  return {{"layer_scale", q.layer_scale}, {"footprint_size", q.footprint_size}, {"substeps", q.substeps}};
}

QualitySettings quality_settings_from_json(const nlohmann::json& j) {
  QualitySettings q;
  q.layer_scale = j.at("layer_scale").get<float>();
  q.footprint_size = j.at("footprint_size").get<int>();
  q.substeps = j.at("substeps").get<int>();
  return q;
}

}  // namespace pyro
