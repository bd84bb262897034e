#pragma once
// `pyro bake-flipbook --six-way` (command_six_way.cpp): the flame bake's options, six-way
// lightmaps instead of flame frames (tools/bake/six_way_bake.h).
#include <string>

#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/flipbook_bake.h"

namespace pyro::cli {

void run_six_way_bake(const SceneDescription& scene, const std::string& scene_file,
                      const std::string& out, const FlipbookBakeOptions& options, bool json);

}  // namespace pyro::cli
