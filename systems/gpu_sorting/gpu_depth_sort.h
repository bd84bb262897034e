#pragma once
// The Gaussian splats' draw order made on the GPU by compute shaders: the sorting system's order
// (systems/sorting/depth_sort.h: culled, then back to front by depth, set and id), the same
// indices, without the CPU touching a key. Four programs (content/shaders):
//  - depth_keys.comp: each particle's key and culling, the kept ones appended;
//  - per 4-bit digit of the key, least significant first: radix_count.comp (per block and digit
//    counts), radix_scan.comp (their prefix sum), radix_scatter.comp (a stable move);
// then the sorted elements' values are the draw order, and the indirect draw command's instance
// count is the particles kept. The passes run over the tie-break's significant digits and the
// depth's 8 (systems/sorting/gpu_key_layout.h).
#include <cstdint>
#include <vector>

#include <epoxy/gl.h>

#include "components/draw_list.h"
#include "engine/gpu/buffer_range.h"
#include "engine/gpu/gl_objects.h"
#include "systems/sorting/gpu_key_layout.h"

namespace pyro {

// The particles to order, already in the GPU's memory: two vec4s a particle (centre and radius,
// then colour and density: the billboard renderer's records), every pool after the one before,
// and each particle's id.
struct GpuParticles {
  gpu::BufferRange records, ids;
  std::vector<uint32_t> set_starts;  // where each set's particles begin, then the total
  GpuKeyLayout layout;
  uint32_t count() const { return set_starts.empty() ? 0u : set_starts.back(); }
};

class GpuDepthSort {
 public:
  // A draw order's elements are 4 uints, the particle's index the third.
  static constexpr GLuint kOrderStride = 4, kOrderOffset = 2;

  GpuDepthSort();

  // Issues the order's dispatches (needs particles.layout.fits()). Afterwards order_buffer()
  // holds the order (kOrderStride uints an entry, the index at kOrderOffset) and
  // command_buffer() a glDrawArraysIndirect command of 4 vertices, one instance per kept
  // particle. A memory barrier for shader storage and commands follows the last dispatch.
  void order(const GpuParticles& particles, const GpuOrderRequest& request);

  GLuint order_buffer() const { return buffers_[final_].get(); }
  GLsizeiptr order_bytes() const { return GLsizeiptr(capacity_) * kElementBytes; }
  GLuint command_buffer() const { return command_.get(); }

  // Read back (waits for the GPU): the particles the last order kept, and the order itself.
  uint32_t read_kept() const;
  std::vector<uint32_t> read_order() const;

 private:
  static constexpr GLsizeiptr kElementBytes = 4 * sizeof(uint32_t);
  void reserve(uint32_t particles);
  void make_keys(const GpuParticles& particles, const GpuOrderRequest& request);
  void radix_pass(uint32_t shift, uint32_t blocks, int from);

  gpu::Program keys_, count_, scan_, scatter_;
  gpu::Buffer buffers_[2], block_counts_, set_starts_, command_;
  uint32_t capacity_ = 0, blocks_capacity_ = 0, set_starts_capacity_ = 0;
  int final_ = 0;
};

}  // namespace pyro
