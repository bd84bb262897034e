#pragma once
// The per-particle instance data of a draw list on the GPU (vec4 attributes at locations 0 and
// 1, 2 for explosion media, 3 for point sprites and 4 for lit media's light, one per instance), for the sphere and
// explosion renderers. Each upload copies the list in parallel into the next slot of a
// persistently mapped ring (engine/gpu/mapped_ring.h), the attributes one region after another.
#include <cstddef>
#include <vector>

#include "components/draw_list.h"
#include "engine/gpu/gl_objects.h"
#include "engine/gpu/mapped_ring.h"

namespace pyro {

// CPU time of uploads since the last reset: copying the instances (the engine's work) and waiting
// for the GPU to release a slot (the driver's).
struct UploadCost {
  double copy_ms = 0.0, wait_ms = 0.0;
  std::size_t bytes = 0;
};

class InstanceBuffer {
 public:
  InstanceBuffer();

  // Copies `list` (gathered: its attribute arrays) into the next slot and returns the vertex
  // array to draw it with. `with_medium`: also list.medium as attribute 2 (explosions), and
  // list.light, where it is not empty, as attribute 4 (lit explosions).
  GLuint upload(const DrawList& list, bool with_medium = false);
  // Attribute 3 of the last upload's instances: `sprites` (as many as the list had).
  void upload_sprites(const std::vector<glm::vec4>& sprites);

  UploadCost cost() const;
  void reset_cost();

 private:
  static constexpr std::size_t kRegions = 5;
  // The first element of attribute region `region` (0-4) of the current slot, and its offset.
  glm::vec4* region(std::size_t region) const;
  std::size_t region_offset(std::size_t region) const;
  void copy(const std::vector<glm::vec4>& from, std::size_t region, std::size_t count);

  gpu::MappedRing ring_;
  unsigned char* slot_ = nullptr;
  std::size_t capacity_ = 0;  // instances per attribute region of the current slot
  gpu::VertexArray vao_;
  double copy_ms_ = 0.0;
  std::size_t bytes_ = 0;
};

}  // namespace pyro
