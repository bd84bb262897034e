#include "systems/runtime/open_scene/open_scene.h"

#include <utility>

#include "systems/runtime/scene/scene_loader.h"

namespace pyro {

std::optional<QualityPick> open_scene_quality(const SceneDescription& scene,
                                              const OpenSceneOptions& options) {
  if (!scene.quality.given()) return std::nullopt;
  std::optional<QualityPick> pick = options.quality;
  if (!pick)
    pick = pick_scene_quality(scene, options.runtime, shared_headless_context().description(),
                              options.on_note);
  if (pick && options.on_note) options.on_note(quality_pick_note(*pick, scene));
  return pick;
}

OpenedScene open_scene(const std::string& path, const OpenSceneOptions& options) {
  OpenedScene opened;
  opened.description = options.description ? *options.description : load_scene(path);
  opened.quality = open_scene_quality(opened.description, options);
  if (options.on_pick) options.on_pick(opened.quality);
  RuntimeOptions runtime = options.runtime;
  if (opened.quality) runtime.quality = opened.quality->settings;
  opened.runtime = std::make_unique<SceneRuntime>(opened.description, runtime);
  return opened;
}

}  // namespace pyro
