#pragma once
// An opaque mesh placed in the scene, drawn before the particles with depth.
#include <memory>

#include "engine/core/enum_names.h"
#include "engine/mesh/mesh_placement.h"
#include "engine/mesh/shared_mesh.h"
#include <glm/vec3.hpp>

namespace pyro {

// The scene file's mesh types: built-in meshes (engine/mesh/mesh_data.h), primitives with sizes,
// and meshes read from files (engine/mesh/mesh_file.h).
enum class MeshKind { ground_plane, water_tower, box, sphere, cylinder, cone, file };
// The scene file's mesh "type" names.
inline constexpr EnumName<MeshKind> mesh_kind_names[] = {
    {MeshKind::ground_plane, "ground_plane"}, {MeshKind::water_tower, "water_tower"},
    {MeshKind::box, "box"},                   {MeshKind::sphere, "sphere"},
    {MeshKind::cylinder, "cylinder"},         {MeshKind::cone, "cone"},
    {MeshKind::file, "file"}};
constexpr const auto& enum_names(MeshKind) { return mesh_kind_names; }

struct MeshInstance {
  MeshKind kind = MeshKind::ground_plane;
  std::shared_ptr<const SharedMesh> geometry;  // in model space; null: nothing drawn
  MeshPlacement placement;                     // model space to world space
  glm::vec3 color{0.5f, 0.5f, 0.5f};           // linear albedo
};

}  // namespace pyro
