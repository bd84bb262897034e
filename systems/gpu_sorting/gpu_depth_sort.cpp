#include "systems/gpu_sorting/gpu_depth_sort.h"

#include <algorithm>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include "engine/gpu/shader_program.h"
#include "systems/sorting/depth_sort.h"

namespace pyro {

namespace {

// content/shaders/radix_sort.glsl's block: 256 threads of 16 elements.
constexpr uint32_t kBlockElements = 256 * 16;
constexpr uint32_t kBuckets = 16;
constexpr uint32_t kKeyThreads = 256;  // depth_keys.comp's work group
constexpr int kMaxViews = 8;           // depth_keys.comp's MAX_VIEWS

uint32_t blocks_for(uint32_t elements) { return (elements + kBlockElements - 1) / kBlockElements; }

void bind(GLuint binding, const gpu::Buffer& buffer) {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer.get());
}

gpu::Buffer storage(GLsizeiptr bytes) {
  gpu::Buffer b = gpu::make_buffer();
  glNamedBufferStorage(b.get(), std::max<GLsizeiptr>(bytes, 16), nullptr, GL_DYNAMIC_STORAGE_BIT);
  return b;
}

}  // namespace

GpuDepthSort::GpuDepthSort()
    : keys_(gpu::load_compute_program("depth_keys.comp")),
      count_(gpu::load_compute_program("radix_count.comp")),
      scan_(gpu::load_compute_program("radix_scan.comp")),
      scatter_(gpu::load_compute_program("radix_scatter.comp")),
      command_(storage(4 * sizeof(uint32_t))) {}

void GpuDepthSort::reserve(uint32_t particles) {
  if (particles > capacity_ || !buffers_[0]) {
    capacity_ = std::max(particles, capacity_ + capacity_ / 2);
    for (gpu::Buffer& b : buffers_) b = storage(GLsizeiptr(capacity_) * kElementBytes);
  }
  const uint32_t blocks = blocks_for(capacity_);
  if (blocks > blocks_capacity_ || !block_counts_) {
    blocks_capacity_ = blocks;
    block_counts_ = storage(GLsizeiptr(blocks) * kBuckets * sizeof(uint32_t));
  }
}

void GpuDepthSort::make_keys(const GpuParticles& in, const GpuOrderRequest& r) {
  if (r.views.size() > size_t(kMaxViews))
    throw std::invalid_argument("GpuDepthSort: at most 8 views cull one list, got " +
                                std::to_string(r.views.size()));
  // The last draw from these buffers (another eye's, or the last frame's) reads them first.
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  const uint32_t initial[4] = {4, 0, 0, 0};  // 4 vertices, no instance kept yet
  glNamedBufferSubData(command_.get(), 0, sizeof(initial), initial);
  glNamedBufferSubData(set_starts_.get(), 0, GLsizeiptr(in.set_starts.size() * sizeof(uint32_t)),
                       in.set_starts.data());
  glUseProgram(keys_.get());
  glUniform1ui(gpu::uniform_location(keys_, "u_particles"), in.count());
  glUniform1ui(gpu::uniform_location(keys_, "u_sets"), uint32_t(in.set_starts.size() - 1));
  glUniform1ui(gpu::uniform_location(keys_, "u_id_bits"), in.layout.id_bits);
  glUniform3fv(gpu::uniform_location(keys_, "u_eye"), 1, glm::value_ptr(r.eye));
  glUniform3fv(gpu::uniform_location(keys_, "u_forward"), 1, glm::value_ptr(r.forward));
  glUniform1i(gpu::uniform_location(keys_, "u_by_eye_distance"), r.by_eye_distance ? 1 : 0);
  glUniform1i(gpu::uniform_location(keys_, "u_views"), GLint(r.views.size()));
  if (!r.views.empty())
    glUniform4fv(gpu::uniform_location(keys_, "u_planes"), GLsizei(6 * r.views.size()),
                 glm::value_ptr(r.views[0].planes[0]));
  glUniform1f(gpu::uniform_location(keys_, "u_cull_radii"), kCullRadii);
  in.records.bind(GL_SHADER_STORAGE_BUFFER, 0);
  in.ids.bind(GL_SHADER_STORAGE_BUFFER, 1);
  bind(2, set_starts_);
  bind(3, command_);
  bind(4, buffers_[0]);
  glDispatchCompute((in.count() + kKeyThreads - 1) / kKeyThreads, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuDepthSort::radix_pass(uint32_t shift, uint32_t blocks, int from) {
  bind(4, buffers_[from]);
  bind(5, buffers_[1 - from]);
  bind(6, block_counts_);
  glUseProgram(count_.get());
  glUniform1ui(gpu::uniform_location(count_, "u_shift"), shift);
  glDispatchCompute(blocks, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(scan_.get());
  glUniform1ui(gpu::uniform_location(scan_, "u_entries"), blocks * kBuckets);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(scatter_.get());
  glUniform1ui(gpu::uniform_location(scatter_, "u_shift"), shift);
  glDispatchCompute(blocks, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuDepthSort::order(const GpuParticles& in, const GpuOrderRequest& r) {
  if (!in.layout.fits())
    throw std::invalid_argument("GpuDepthSort: the sets' ranks and ids need more than 32 bits");
  if (in.set_starts.size() < 2) throw std::invalid_argument("GpuDepthSort: no particle sets");
  reserve(in.count());
  if (in.set_starts.size() > set_starts_capacity_) {
    set_starts_capacity_ = uint32_t(in.set_starts.size());
    set_starts_ = storage(GLsizeiptr(set_starts_capacity_ * sizeof(uint32_t)));
  }
  make_keys(in, r);
  const uint32_t blocks = std::max(1u, blocks_for(in.count()));
  int from = 0;
  for (uint32_t digit = 0; digit < in.layout.tie_break_digits(); ++digit, from = 1 - from)
    radix_pass(4 * digit, blocks, from);
  for (uint32_t shift = 32; shift < 64; shift += 4, from = 1 - from) radix_pass(shift, blocks, from);
  final_ = from;
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

uint32_t GpuDepthSort::read_kept() const {
  uint32_t command[4] = {};
  glGetNamedBufferSubData(command_.get(), 0, sizeof(command), command);
  return command[1];
}

std::vector<uint32_t> GpuDepthSort::read_order() const {
  const uint32_t kept = read_kept();
  std::vector<uint32_t> elements(size_t(kept) * kOrderStride);
  glGetNamedBufferSubData(order_buffer(), 0, GLsizeiptr(elements.size() * sizeof(uint32_t)),
                          elements.data());
  std::vector<uint32_t> order(kept);
  for (size_t k = 0; k < kept; ++k) order[k] = elements[k * kOrderStride + kOrderOffset];
  return order;
}

}  // namespace pyro
