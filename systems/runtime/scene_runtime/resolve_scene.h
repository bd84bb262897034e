#pragma once
// The first layer of the runtime: description + options -> ResolvedScene. Merges the options
// over the scene's own choices, applies a quality pick and refuses a scene over its budget
// (particles without the volumes' yet, memory, texture size) before anything is allocated.
// Plain inputs and outputs: no GL, no files, no world.
#include <cstdint>

#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/resolved_scene.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

// `driver_max_texture` stands for the budget's texture_size 0 (the driver's GL_MAX_TEXTURE_SIZE).
// Throws UserError(scene file, "/budget/...", ...) when the scene exceeds its budget.
ResolvedScene resolve_scene(const SceneDescription& scene, const RuntimeOptions& options,
                            int driver_max_texture);

// The budget check again, with the particles the volumes turned out to hold (load_scene_assets
// calls it once they are read, before the world is built).
void check_resolved_budget(const ResolvedScene& resolved, uint64_t volume_particles);

}  // namespace pyro
