#pragma once
// The second layer of the runtime: ResolvedScene -> SceneAssets. Reads every file the scene
// names (mesh files, volumes, flipbooks; the engine's default flipbook, default_flipbook.h, for a
// fire that names none: baked before by the front door, refused here when it is not), and checks
// the budget again with the volumes' particles: all before any world exists. Notes (which file a
// volume was read from) go to `on_note` as they happen and into SceneAssets::notes. Errors are UserErrors naming the scene, the entry
// and the file. With a cache (scene_asset_cache.h), volumes and prepared flipbooks whose inputs
// are unchanged since its last load are taken from it instead of being read again.
#include "systems/runtime/scene_runtime/resolved_scene.h"
#include "systems/runtime/scene_runtime/runtime_options.h"
#include "systems/runtime/scene_runtime/scene_assets.h"

namespace pyro {

class SceneAssetCache;

SceneAssets load_scene_assets(const ResolvedScene& resolved, const NoteSink& on_note = {},
                              SceneAssetCache* cache = nullptr);

}  // namespace pyro
