#include "systems/runtime/scene_runtime/scene_inputs.h"

#include "systems/runtime/scene_runtime/default_flipbook.h"

namespace pyro {

std::vector<NamedPath> scene_inputs(const std::string& scene_arg, const SceneDescription& scene) {
  std::vector<NamedPath> inputs;
  if (scene_arg != "-") inputs.push_back({scene_arg, "the scene file"});
  for (const VolumeDescription& v : scene.volumes)
    inputs.push_back({v.path, "the volume file of " + scene_arg + " at " + v.pointer});
  for (const MeshDescription& m : scene.meshes)
    if (!m.path.empty()) inputs.push_back({m.path, "the mesh file of " + scene_arg + " at " + m.pointer});
  for (size_t i = 0; i < scene.fires.size(); ++i) {
    const std::string& folder = scene.fires[i].flipbook;
    inputs.push_back({folder.empty() ? default_flipbook_folder() : folder,
                      "the flipbook of " + scene_arg + " at /fires/" + std::to_string(i)});
  }
  return inputs;
}

}  // namespace pyro
