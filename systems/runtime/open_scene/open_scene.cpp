#include "systems/runtime/open_scene/open_scene.h"

#include <utility>

#include "systems/runtime/open_scene/flipbook_bake.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/default_flipbook.h"
#include "systems/runtime/scene_runtime/scene_asset_cache.h"

namespace pyro {

void prepare_scene_run(const SceneDescription& scene, const RuntimeOptions& options) {
  bool needs_default_flipbook = false;
  for (const FlipbookFire& fire : scene.fires) needs_default_flipbook |= fire.flipbook.empty();
  if (!needs_default_flipbook || default_flipbook_baked()) return;
  if (options.asset_cache) options.asset_cache->count_default_bake();
  ensure_default_flipbook(options.on_note);
}

std::unique_ptr<SceneRuntime> open_runtime(const SceneDescription& scene, const RuntimeOptions& options) {
  prepare_scene_run(scene, options);
  return std::make_unique<SceneRuntime>(scene, options);
}

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
  prepare_scene_run(opened.description, options.runtime);
  opened.quality = open_scene_quality(opened.description, options);
  if (options.on_pick) options.on_pick(opened.quality);
  RuntimeOptions runtime = options.runtime;
  if (opened.quality) runtime.quality = opened.quality->settings;
  opened.runtime = std::make_unique<SceneRuntime>(opened.description, runtime);
  return opened;
}

}  // namespace pyro
