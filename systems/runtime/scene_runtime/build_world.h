#pragma once
// The third layer of the runtime: ResolvedScene + SceneAssets -> World. Entities (a camera,
// one per cloud, volume, emitter, mesh and fire) and resources (settings, shading, clock,
// environment, GPU targets, footprint table, flipbook textures), then the scene's prewarm steps.
// Reads no file (the assets hold what files gave); needs the OpenGL context the world will
// render with to be current (targets and textures are made here).
#include "engine/ecs/world.h"
#include "systems/runtime/scene_runtime/resolved_scene.h"
#include "systems/runtime/scene_runtime/scene_assets.h"

namespace pyro {

ecs::World build_world(const ResolvedScene& resolved, SceneAssets assets);

}  // namespace pyro
