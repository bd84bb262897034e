#pragma once
// The per-particle instance data of a draw list on the GPU (vec4 attributes at locations 0 and
// 1, and 2 for explosion media, one per instance), shared by the billboard renderers.
#include "components/draw_list.h"
#include "engine/gpu/gl_objects.h"

namespace pyro {

class InstanceBuffer {
 public:
  InstanceBuffer();
  // Uploads `list` (growing the buffer by half again when it is too small) and returns the
  // vertex array to draw it with. `with_medium`: also list.medium as attribute 2 (explosions).
  GLuint upload(const DrawList& list, bool with_medium = false);

 private:
  gpu::Buffer buffer_;
  size_t capacity_ = 0;
  gpu::VertexArray vao_;
};

}  // namespace pyro
