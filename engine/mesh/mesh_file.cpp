#include "engine/mesh/mesh_file.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "engine/core/user_error.h"
#include "engine/mesh/mesh_file_check.h"

namespace pyro {

namespace {

glm::vec3 transformed_point(const aiMatrix4x4& m, const aiVector3D& p) {
  const aiVector3D q = m * p;
  return {q.x, q.y, q.z};
}

// Normals transform by the inverse transpose of the node's linear part.
glm::mat3 normal_matrix(const aiMatrix4x4& m) {
  const glm::mat3 linear(m.a1, m.b1, m.c1, m.a2, m.b2, m.c2, m.a3, m.b3, m.c3);  // column-major
  return glm::transpose(glm::inverse(linear));
}

// Appends the triangles of `mesh` placed by `to_file` (the product of the node transforms).
void append_mesh(MeshData& out, const aiMesh& mesh, const aiMatrix4x4& to_file) {
  const glm::mat3 normals = normal_matrix(to_file);
  const bool mirrored = to_file.Determinant() < 0.0f;  // the winding turns over
  const bool flat = !mesh.HasNormals();
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines
    unsigned corner[3] = {face.mIndices[0], face.mIndices[1], face.mIndices[2]};
    if (mirrored) std::swap(corner[1], corner[2]);
    glm::vec3 p[3];
    for (int k = 0; k < 3; ++k) p[k] = transformed_point(to_file, mesh.mVertices[corner[k]]);
    const glm::vec3 face_normal = glm::cross(p[1] - p[0], p[2] - p[0]);
    const float area2 = glm::length(face_normal);
    for (int k = 0; k < 3; ++k) {
      glm::vec3 n = area2 > 0.0f ? face_normal / area2 : glm::vec3(0, 1, 0);
      if (!flat) {
        const aiVector3D& a = mesh.mNormals[corner[k]];
        const glm::vec3 placed = normals * glm::vec3(a.x, a.y, a.z);
        if (glm::length(placed) > 0.0f) n = glm::normalize(placed);
      }
      out.indices.push_back(static_cast<uint32_t>(out.positions.size()));
      out.positions.push_back(p[k]);
      out.normals.push_back(n);
    }
  }
}

void append_node(MeshData& out, const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent) {
  const aiMatrix4x4 to_file = parent * node.mTransformation;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) append_mesh(out, *scene.mMeshes[node.mMeshes[i]], to_file);
  for (unsigned c = 0; c < node.mNumChildren; ++c) append_node(out, scene, *node.mChildren[c], to_file);
}

}  // namespace

MeshData read_mesh_file(const std::string& path) {
  check_mesh_file(path);
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  if (scene == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || scene->mRootNode == nullptr)
    throw UserError(path, "", std::string("cannot read the mesh file (truncated or damaged?): ") +
                                  importer.GetErrorString());
  MeshData out;
  append_node(out, *scene, *scene->mRootNode, aiMatrix4x4());
  if (out.indices.empty()) throw UserError(path, "", "the mesh file holds no triangles");
  if (out.triangle_count() > kMaxMeshFileTriangles)
    throw UserError(path, "", "the file holds " + std::to_string(out.triangle_count()) +
                                  " triangles, more than the limit of " + std::to_string(kMaxMeshFileTriangles));
  return out;
}

}  // namespace pyro
