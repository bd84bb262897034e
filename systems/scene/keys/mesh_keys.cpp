// "meshes[]": opaque scenery.
#include "components/mesh_instance.h"
#include "systems/scene/scene_description.h"
#include "systems/scene/scene_keys.h"

namespace pyro {

const ParameterTable& mesh_keys() {
  static const MeshDescription d{};
  static const ParameterTable table{
      "meshes[]", "A built-in opaque mesh.",
      {enum_key<MeshKind>("type", "Which built-in mesh.").as_required(),
       vec3_key("position", kAnyRange, "Where the mesh's origin is placed.").with_default(d.position),
       number_key("scale", kPositive, "Uniform scale; for the ground plane, half the side length.")
           .with_default(d.scale),
       vec3_key("color", kUnit, "Linear albedo.").with_default(d.color)}};
  return table;
}

}  // namespace pyro
