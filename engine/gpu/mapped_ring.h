#pragma once
// A persistently mapped buffer (ARB_buffer_storage, core since OpenGL 4.4) split into kSlots
// slots, for data the CPU writes every frame and the GPU reads: each next() hands out the slot
// after the last one, first waiting for the fence set when that slot was last given to the GPU.
// So writing never waits for draws that read the previous slot, and the CPU writes straight
// into the memory the GPU reads (no copy by the driver).
#include <array>
#include <cstddef>

#include <epoxy/gl.h>

#include "engine/gpu/gl_objects.h"

namespace pyro::gpu {

class MappedRing {
 public:
  static constexpr int kSlots = 2;

  MappedRing() = default;
  ~MappedRing();
  MappedRing(MappedRing&& other) noexcept;
  MappedRing& operator=(MappedRing&& other) noexcept;

  // The next slot, at least `bytes` long (the buffer grows by half again when a slot is too
  // small; the old one lives on in the driver until the draws reading it are done). Everything
  // issued to the GPU before this call may still read the slot handed out before.
  unsigned char* next(std::size_t bytes);
  GLuint buffer() const { return buffer_.get(); }
  // Where the current slot begins in buffer().
  std::size_t offset() const { return static_cast<std::size_t>(slot_) * slot_bytes_; }
  std::size_t slot_bytes() const { return slot_bytes_; }
  // Milliseconds next() has waited for the GPU since the last reset.
  double wait_ms() const { return wait_ms_; }
  void reset_wait() { wait_ms_ = 0.0; }

 private:
  void delete_fences();
  void grow(std::size_t bytes);

  Buffer buffer_;
  unsigned char* mapped_ = nullptr;
  std::size_t slot_bytes_ = 0;
  int slot_ = 0;
  std::array<GLsync, kSlots> fences_{};  // set when the GPU was given the slot, until reused
  double wait_ms_ = 0.0;
};

}  // namespace pyro::gpu
