#pragma once
// The per-particle instance data of a draw list on the GPU (vec4 attributes at locations 0 and
// 1, 2 for explosion media, and 3 for point sprites, one per instance), shared by the billboard
// renderers.
#include "components/draw_list.h"
#include "engine/gpu/gl_objects.h"

namespace pyro {

class InstanceBuffer {
 public:
  InstanceBuffer();
  // Uploads `list` (growing the buffer by half again when it is too small) and returns the
  // vertex array to draw it with. `with_medium`: also list.medium as attribute 2 (explosions).
  GLuint upload(const DrawList& list, bool with_medium = false);
  // Attribute 3 of the last upload's instances: `sprites` (as many as the list had).
  void upload_sprites(const std::vector<glm::vec4>& sprites);

 private:
  gpu::Buffer buffer_;
  size_t capacity_ = 0;  // instances per attribute region (four regions)
  gpu::VertexArray vao_;
};

}  // namespace pyro
