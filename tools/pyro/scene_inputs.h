#pragma once
// The files a command that runs a scene reads, which none of its outputs may replace
// (engine/core/same_file.h).
#include <string>
#include <vector>

#include "engine/core/same_file.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro::cli {

inline std::vector<NamedPath> scene_inputs(const std::string& scene_arg, const SceneDescription& scene) {
  std::vector<NamedPath> inputs;
  if (scene_arg != "-") inputs.push_back({scene_arg, "the scene file"});
  for (const VolumeDescription& v : scene.volumes)
    inputs.push_back({v.path, "the volume file of " + scene_arg + " at " + v.pointer});
  return inputs;
}

}  // namespace pyro::cli
