#pragma once
// The front door of the engine: how every command, the viewer and an embedding program open a
// scene file to run it.
//   scene file --load_scene--> SceneDescription
//              --prepare_scene_run--> what the run needs made first (the default flame
//                                 flipbook baked: flipbook_bake.h)
//              --quality pick--> QualityPick (scene key quality.max_rmse: handed in, else the
//                                 cache's, else measured now and cached; quality_picker.h)
//              --RuntimeOptions::quality--> SceneRuntime (scene_runtime.h)
// A scene without a quality target opens with the options as given. The quality measurement
// itself (quality_measurement.h) runs its own runtimes behind this door, of scenes it prepared.
// A scene held in memory and run as written (no pick: a bake's own scene, an analysis) opens
// through open_runtime. The runtime (scene_runtime.h) bakes nothing: it refuses a scene whose
// default flipbook is not baked.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "systems/runtime/quality_picker/quality_picker.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/runtime_options.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

struct OpenSceneOptions {
  // How the scene runs (size, stereo, overrides, context, the assets' notes). Its `quality` is
  // replaced by the pick when the scene sets a target.
  RuntimeOptions runtime;
  // The scene already loaded (a viewer that holds it, a scene read once for checks before
  // anything runs): used instead of loading the path again.
  std::optional<SceneDescription> description;
  // A pick made before (pyro render: the one recorded with an output folder's run, so that every
  // range of the run draws with it): used as is, nothing looked up or measured. Only for a scene
  // with a quality target.
  std::optional<QualityPick> quality;
  // The pick's notes: a measurement starting, a cache that cannot be written, and the pick itself
  // (quality_pick_note) once made.
  NoteSink on_note;
  // Called with the pick (none when the scene sets no target) after it is made and before the
  // runtime is built: pyro render records it with its run here.
  std::function<void(const std::optional<QualityPick>&)> on_pick;
};

struct OpenedScene {
  SceneDescription description;        // as loaded (the pick not applied: runtime->scene() is)
  std::optional<QualityPick> quality;  // the pick applied; none without a target
  std::unique_ptr<SceneRuntime> runtime;
};

// The pick `scene` runs with under `options`: the one handed in, else the cache's or one
// measured now (at the size the runtime options give, on the shared headless context's
// renderer); none when the scene sets no quality target. Its note goes to options.on_note.
std::optional<QualityPick> open_scene_quality(const SceneDescription& scene,
                                              const OpenSceneOptions& options);

// What a run of `scene` needs before any runtime (or a quality measurement) opens it: the
// engine's default flame flipbook baked (ensure_default_flipbook, flipbook_bake.h) when a fire
// names no `flipbook` and it is not baked yet, with a note to options.on_note before the bake
// starts, counted by options.asset_cache (SceneAssetCounters::flipbooks_baked). Nothing when
// nothing is missing. Whoever computes a run's identity (run_identity.h, whose assets include the
// default flipbook) or measures a quality pick without open_scene prepares first.
void prepare_scene_run(const SceneDescription& scene, const RuntimeOptions& options = {});

// `scene`, held in memory, prepared and opened as written (no quality pick) with `options`.
std::unique_ptr<SceneRuntime> open_runtime(const SceneDescription& scene,
                                           const RuntimeOptions& options = {});

// Loads `path` (unless options.description holds it), prepares it (prepare_scene_run, with
// options.runtime), picks the quality, and builds the runtime with the pick applied. Throws UserError for a scene file (or a budget) the user can
// mend, as load_scene and SceneRuntime do.
OpenedScene open_scene(const std::string& path, const OpenSceneOptions& options = {});

}  // namespace pyro
