#pragma once
// The identity of a `pyro render` run (systems/runtime/scene_runtime/run_identity.h) from the command's
// options: what keys its output folder. `pyro farm submit` computes the same for the job its
// tasks run, so that `pyro farm collect` can tell their frames apart from another run's.
#include <nlohmann/json.hpp>
#include <string>

#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

// What changes the pixels besides the scene and its assets, as the run resolves them before any
// quality pick (a pick is recorded with the run instead: OutputFolder::recorded).
nlohmann::json pixel_settings(const SceneDescription& scene, const RuntimeOptions& options);

// {"digest", "parts", "scene_file"} of rendering `scene` (read from `scene_file`) with `options`
// (width and height overrides applied); `exr_depth` for --format exr --depth. The scene is
// prepared first by the caller (prepare_scene_run, systems/runtime/open_scene/open_scene.h: the
// default flipbook baked, whose folder the identity digests); nothing is baked here.
nlohmann::json render_identity_json(const SceneDescription& scene, const RuntimeOptions& options,
                                    const std::string& scene_file, bool exr_depth);

}  // namespace pyro
