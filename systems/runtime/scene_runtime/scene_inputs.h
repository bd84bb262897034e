#pragma once
// Every file and folder a run of a scene reads: the scene file, its volume files and particle
// sequences, its mesh files and its fires' flipbooks (the engine's default one included). None
// of a command's outputs may replace or lie inside them (the gate: engine/io/output_gate.h).
#include <string>
#include <vector>

#include "engine/io/output_gate.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

// `scene_arg` is the scene as named on the command line ("-": standard input, not a file).
std::vector<NamedPath> scene_inputs(const std::string& scene_arg, const SceneDescription& scene);

}  // namespace pyro
