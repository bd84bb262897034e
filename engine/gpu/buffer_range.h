#pragma once
// A part of a GL buffer: what glBindBufferRange binds.
#include <epoxy/gl.h>

namespace pyro::gpu {

struct BufferRange {
  GLuint buffer = 0;
  GLintptr offset = 0;
  GLsizeiptr bytes = 0;

  void bind(GLenum target, GLuint index) const { glBindBufferRange(target, index, buffer, offset, bytes); }
};

}  // namespace pyro::gpu
