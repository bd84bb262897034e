#include "systems/billboard_render/instance_buffer.h"

#include <algorithm>

namespace pyro {

InstanceBuffer::InstanceBuffer() : buffer_(gpu::make_buffer()), vao_(gpu::make_vertex_array()) {}

GLuint InstanceBuffer::upload(const DrawList& list, bool with_medium) {
  const size_t n = list.size();
  if (n > capacity_) {
    buffer_ = gpu::make_buffer();
    capacity_ = n + n / 2;
    glNamedBufferStorage(buffer_.get(), static_cast<GLsizeiptr>(4 * capacity_ * sizeof(glm::vec4)),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  const size_t bytes = n * sizeof(glm::vec4);
  const size_t second = capacity_ * sizeof(glm::vec4);
  glNamedBufferSubData(buffer_.get(), 0, static_cast<GLsizeiptr>(bytes), list.center_radius.data());
  glNamedBufferSubData(buffer_.get(), static_cast<GLintptr>(second), static_cast<GLsizeiptr>(bytes),
                       list.color_density.data());
  if (with_medium)
    glNamedBufferSubData(buffer_.get(), static_cast<GLintptr>(2 * second), static_cast<GLsizeiptr>(bytes),
                         list.medium.data());
  const GLuint vao = vao_.get();
  glVertexArrayVertexBuffer(vao, 0, buffer_.get(), 0, sizeof(glm::vec4));
  glVertexArrayVertexBuffer(vao, 1, buffer_.get(), static_cast<GLintptr>(second), sizeof(glm::vec4));
  glVertexArrayVertexBuffer(vao, 2, buffer_.get(), static_cast<GLintptr>(2 * second), sizeof(glm::vec4));
  glVertexArrayVertexBuffer(vao, 3, buffer_.get(), static_cast<GLintptr>(3 * second), sizeof(glm::vec4));
  const GLuint attributes = with_medium ? 3 : 2;
  if (!with_medium) glDisableVertexArrayAttrib(vao, 2);  // reads the default (0, 0, 0, 1)
  for (GLuint a = 0; a < attributes; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, a, a);
    glVertexArrayBindingDivisor(vao, a, 1);
  }
  return vao;
}

void InstanceBuffer::upload_sprites(const std::vector<glm::vec4>& sprites) {
  if (sprites.empty()) return;
  const GLuint vao = vao_.get();
  glNamedBufferSubData(buffer_.get(), static_cast<GLintptr>(3 * capacity_ * sizeof(glm::vec4)),
                       static_cast<GLsizeiptr>(std::min(sprites.size(), capacity_) * sizeof(glm::vec4)),
                       sprites.data());
  glEnableVertexArrayAttrib(vao, 3);
  glVertexArrayAttribFormat(vao, 3, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao, 3, 3);
  glVertexArrayBindingDivisor(vao, 3, 1);
}

}  // namespace pyro
