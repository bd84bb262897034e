#pragma once
// The per-particle instance data of a draw list on the GPU (two vec4 attributes, locations 0
// and 1, one per instance), shared by the billboard renderers.
#include "components/draw_list.h"
#include "engine/gpu/gl_objects.h"

namespace pyro {

class InstanceBuffer {
 public:
  InstanceBuffer();
  // Uploads `list` (growing the buffer by half again when it is too small) and returns the
  // vertex array to draw it with.
  GLuint upload(const DrawList& list);

 private:
  gpu::Buffer buffer_;
  size_t capacity_ = 0;
  gpu::VertexArray vao_;
};

}  // namespace pyro
