#pragma once
// A triangle mesh shared by whatever draws or places it: immutable once made, with an identity
// that no other mesh of this process has (a GPU cache keys its buffers by it).
#include <cstdint>
#include <memory>

#include "engine/mesh/mesh_data.h"

namespace pyro {

struct SharedMesh {
  MeshData data;
  // Seen only from outside (a closed surface wound counter-clockwise outside): back faces may be
  // culled. Otherwise both sides are drawn and shaded.
  bool closed = false;
  uint64_t id = 0;  // unique in this process, never 0
};

std::shared_ptr<const SharedMesh> share_mesh(MeshData data, bool closed);

}  // namespace pyro
