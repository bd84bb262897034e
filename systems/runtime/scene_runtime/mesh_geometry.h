#pragma once
// The model-space geometry of a scene's mesh entry (docs/scene_format.md, meshes[]): a built-in
// mesh at unit scale, a primitive at its size standing on its origin, or a mesh file read
// (engine/mesh/mesh_file.h) with the scene entry named in its errors.
#include <memory>

#include "engine/mesh/shared_mesh.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

// Segments around the y axis of the round primitives (and rings of the sphere: half as many).
inline constexpr int kPrimitiveSegments = 32;

// Every kind but MeshKind::file.
std::shared_ptr<const SharedMesh> primitive_geometry(const MeshDescription& mesh);

// MeshKind::file: throws UserError naming the scene file, the entry's JSON pointer, the mesh
// file and what went wrong.
std::shared_ptr<const SharedMesh> file_geometry(const SceneDescription& scene, const MeshDescription& mesh);

}  // namespace pyro
