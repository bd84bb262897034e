#include "systems/runtime/scene_runtime/mesh_geometry.h"

#include "engine/core/user_error.h"
#include "engine/mesh/mesh_file.h"

namespace pyro {

std::shared_ptr<const SharedMesh> primitive_geometry(const MeshDescription& m) {
  const float half = 0.5f;
  switch (m.kind) {
    case MeshKind::ground_plane:
      // A single sheet, seen from both sides.
      return share_mesh(make_ground_plane(1.0f), false);
    case MeshKind::water_tower:
      return share_mesh(make_water_tower(), true);
    case MeshKind::box:
      return share_mesh(make_box({-half * m.size.x, 0.0f, -half * m.size.z}, {half * m.size.x, m.size.y, half * m.size.z}),
                        true);
    case MeshKind::sphere:
      return share_mesh(make_sphere(m.radius, {0.0f, m.radius, 0.0f}, kPrimitiveSegments, kPrimitiveSegments / 2),
                        true);
    case MeshKind::cylinder:
      return share_mesh(make_cylinder(m.radius, 0.0f, m.height, kPrimitiveSegments), true);
    case MeshKind::cone:
      return share_mesh(make_cone(m.radius, 0.0f, m.height, kPrimitiveSegments), true);
    case MeshKind::file:
      break;
  }
  return nullptr;
}

std::shared_ptr<const SharedMesh> file_geometry(const SceneDescription& scene, const MeshDescription& m) {
  try {
    // Not known to be closed: both sides drawn.
    return share_mesh(read_mesh_file(m.path), false);
  } catch (const UserError& e) {
    throw UserError(scene.file, m.pointer, "mesh file \"" + m.path + "\": " + e.expected());
  }
}

}  // namespace pyro
