#pragma once
// Triangle meshes read from glTF 2.0 (.gltf, .glb) and OBJ files (through Assimp, which only
// this module's source sees): every mesh that the file's node hierarchy places, with the nodes'
// transforms applied, in one MeshData. Points and lines are dropped; polygons are triangulated.
// Normals are the file's where it has them; a mesh without normals gets flat normals (each
// triangle its own three vertices). Materials, textures, cameras, lights and animations are
// ignored. The file is checked first (mesh_file_check.h): a file over the triangle limit is
// refused before its geometry is read. Errors: UserError(path, place, what).
#include <string>

#include "engine/mesh/mesh_data.h"

namespace pyro {

MeshData read_mesh_file(const std::string& path);

}  // namespace pyro
