#include "systems/billboard_render/instance_buffer.h"

#include <algorithm>
#include <chrono>

#include "systems/billboard_render/parallel_copy.h"

namespace pyro {

InstanceBuffer::InstanceBuffer() : vao_(gpu::make_vertex_array()) {}

std::size_t InstanceBuffer::region_offset(std::size_t region) const {
  return ring_.offset() + region * capacity_ * sizeof(glm::vec4);
}

glm::vec4* InstanceBuffer::region(std::size_t region) const {
  return reinterpret_cast<glm::vec4*>(slot_ + region * capacity_ * sizeof(glm::vec4));
}

void InstanceBuffer::copy(const std::vector<glm::vec4>& from, std::size_t region_index, std::size_t count) {
  const auto start = std::chrono::steady_clock::now();
  parallel_copy(region(region_index), from.data(), count * sizeof(glm::vec4));
  copy_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  bytes_ += count * sizeof(glm::vec4);
}

UploadCost InstanceBuffer::cost() const { return {copy_ms_, ring_.wait_ms(), bytes_}; }

void InstanceBuffer::reset_cost() {
  copy_ms_ = 0.0;
  bytes_ = 0;
  ring_.reset_wait();
}

GLuint InstanceBuffer::upload(const DrawList& list, bool with_medium) {
  const std::size_t n = list.size();
  slot_ = ring_.next(kRegions * std::max<std::size_t>(n, 1) * sizeof(glm::vec4));
  capacity_ = ring_.slot_bytes() / (kRegions * sizeof(glm::vec4));
  copy(list.center_radius, 0, n);
  copy(list.color_density, 1, n);
  if (with_medium) copy(list.medium, 2, n);
  const bool with_light = with_medium && list.light.size() == n;
  if (with_light) copy(list.light, 4, n);
  const GLuint vao = vao_.get();
  for (std::size_t a = 0; a < kRegions; ++a)
    glVertexArrayVertexBuffer(vao, static_cast<GLuint>(a), ring_.buffer(),
                              static_cast<GLintptr>(region_offset(a)), sizeof(glm::vec4));
  // Attributes left out read the default (0, 0, 0, 1).
  for (GLuint a : {0u, 1u, 2u, 4u}) {
    if ((a == 2 && !with_medium) || (a == 4 && !with_light)) {
      glDisableVertexArrayAttrib(vao, a);
      continue;
    }
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, a, a);
    glVertexArrayBindingDivisor(vao, a, 1);
  }
  return vao;
}

void InstanceBuffer::upload_sprites(const std::vector<glm::vec4>& sprites) {
  if (sprites.empty() || !slot_) return;
  copy(sprites, 3, std::min(sprites.size(), capacity_));
  const GLuint vao = vao_.get();
  glEnableVertexArrayAttrib(vao, 3);
  glVertexArrayAttribFormat(vao, 3, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao, 3, 3);
  glVertexArrayBindingDivisor(vao, 3, 1);
}

}  // namespace pyro
