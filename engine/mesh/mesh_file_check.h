#pragma once
// What a mesh file claims before it is read: its format by extension and its triangle count,
// from the glTF JSON (the accessors' counts; a .glb's header and JSON chunk only) or from a
// pre-scan of an OBJ's face lines, so that a file over the limit is refused without loading its
// geometry. A file that cannot be opened, a .glb whose length disagrees with its header, or a
// glTF whose JSON is not valid is refused here too. Errors: UserError(path, place, what).
#include <cstdint>
#include <optional>
#include <string>

namespace pyro {

// The most triangles one mesh file may hold (after triangulation, counting every node that
// places a mesh): 20 million, about 1 GB of vertex data once read.
inline constexpr uint64_t kMaxMeshFileTriangles = 20'000'000;

enum class MeshFileFormat { gltf, glb, obj };

// By the path's extension (any case): ".gltf", ".glb" or ".obj"; none otherwise.
std::optional<MeshFileFormat> mesh_file_format(const std::string& path);

// The triangles the file claims; throws UserError when it cannot be read, is malformed as far as
// this check reads, or claims more than kMaxMeshFileTriangles.
uint64_t check_mesh_file(const std::string& path);

}  // namespace pyro
