#include "engine/mesh/shared_mesh.h"

#include <atomic>
#include <utility>

namespace pyro {

std::shared_ptr<const SharedMesh> share_mesh(MeshData data, bool closed) {
  static std::atomic<uint64_t> next_id{1};
  return std::make_shared<const SharedMesh>(SharedMesh{std::move(data), closed, next_id++});
}

}  // namespace pyro
