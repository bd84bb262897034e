// "meshes[]": opaque scenery.
#include "components/mesh_instance.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

const ParameterTable& mesh_keys() {
  static const MeshDescription d{};
  static const ParameterTable table{
      "meshes[]",
      "An opaque mesh: a built-in one, a primitive (standing on its origin, rising along +y) or a "
      "glTF 2.0 / OBJ file.",
      {enum_key<MeshKind>("type", "Which mesh.").as_required(),
       vec3_key("position", kAnyRange, "Where the mesh's origin is placed.").with_default(d.position),
       vec3_key("rotation_deg", kAnyRange,
                "Euler angles in degrees about the x, y and z axes, applied in that order, about the origin.")
           .with_default(d.rotation_deg),
       number_key("scale", kPositive, "Uniform scale; for the ground plane, half the side length.")
           .with_default(d.scale),
       vec3_key("color", kUnit, "Linear albedo (a file's own materials are ignored).").with_default(d.color),
       vec3_key("size", kPositive, "Box: full extents along x, y and z.")
           .with_default(d.size)
           .only_for("type", {"box"}),
       number_key("radius", kPositive, "Sphere, cylinder, cone: the radius.")
           .with_default(d.radius)
           .only_for("type", {"sphere", "cylinder", "cone"}),
       number_key("height", kPositive, "Cylinder, cone: the height above the base.")
           .with_default(d.height)
           .only_for("type", {"cylinder", "cone"}),
       string_key("file",
                  "File: a .gltf, .glb or .obj file, relative to the scene file's folder; required.")
           .as_required()
           .only_for("type", {"file"})}};
  return table;
}

}  // namespace pyro
