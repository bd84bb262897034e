#pragma once
// An opaque procedural mesh placed in the scene, drawn before the particles with depth.
#include <glm/vec3.hpp>

namespace pyro {

// The procedural meshes (engine/mesh/mesh_data.h).
enum class MeshKind { ground_plane, water_tower };

struct MeshInstance {
  MeshKind kind = MeshKind::ground_plane;
  glm::vec3 position{0.0f, 0.0f, 0.0f};
  float scale = 1.0f;
  glm::vec3 color{0.5f, 0.5f, 0.5f};  // linear albedo
};

}  // namespace pyro
