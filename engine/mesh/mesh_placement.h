#pragma once
// Where a mesh stands: model space to world space as p_world = position + scale R p_model, with
// R = Rz(z) Ry(y) Rx(x) for Euler angles in degrees: the rotation about x applies first, then
// about y, then about z (all about the world's axes through the mesh's origin).
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace pyro {

struct MeshPlacement {
  glm::vec3 position{0.0f};
  glm::vec3 rotation_deg{0.0f};
  float scale = 1.0f;  // uniform, > 0

  glm::mat3 rotation() const;
  glm::mat4 model_matrix() const;
  glm::vec3 apply(const glm::vec3& p) const { return position + scale * (rotation() * p); }
};

}  // namespace pyro
