#pragma once
// An opaque procedural mesh placed in the scene, drawn before the particles with depth.
#include "engine/core/enum_names.h"
#include <glm/vec3.hpp>

namespace pyro {

// The procedural meshes (engine/mesh/mesh_data.h).
enum class MeshKind { ground_plane, water_tower };
// The scene file's mesh "type" names.
inline constexpr EnumName<MeshKind> mesh_kind_names[] = {{MeshKind::ground_plane, "ground_plane"},
                                                      {MeshKind::water_tower, "water_tower"}};
constexpr const auto& enum_names(MeshKind) { return mesh_kind_names; }

struct MeshInstance {
  MeshKind kind = MeshKind::ground_plane;
  glm::vec3 position{0.0f, 0.0f, 0.0f};
  float scale = 1.0f;
  glm::vec3 color{0.5f, 0.5f, 0.5f};  // linear albedo
};

}  // namespace pyro
