#include "engine/gpu/mapped_ring.h"

#include <chrono>
#include <utility>

namespace pyro::gpu {

namespace {
constexpr GLbitfield kMapping = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
}  // namespace

MappedRing::~MappedRing() { delete_fences(); }

MappedRing::MappedRing(MappedRing&& o) noexcept
    : buffer_(std::move(o.buffer_)),
      mapped_(std::exchange(o.mapped_, nullptr)),
      slot_bytes_(std::exchange(o.slot_bytes_, 0)),
      slot_(o.slot_),
      fences_(std::exchange(o.fences_, {})),
      wait_ms_(o.wait_ms_) {}

MappedRing& MappedRing::operator=(MappedRing&& o) noexcept {
  if (this == &o) return *this;
  delete_fences();
  buffer_ = std::move(o.buffer_);
  mapped_ = std::exchange(o.mapped_, nullptr);
  slot_bytes_ = std::exchange(o.slot_bytes_, 0);
  slot_ = o.slot_;
  fences_ = std::exchange(o.fences_, {});
  wait_ms_ = o.wait_ms_;
  return *this;
}

void MappedRing::delete_fences() {
  for (GLsync& f : fences_) {
    if (f) glDeleteSync(f);
    f = nullptr;
  }
}

void MappedRing::grow(std::size_t bytes) {
  delete_fences();
  buffer_ = make_buffer();
  // Slots start on 256-byte boundaries (every binding's offset alignment).
  slot_bytes_ = ((bytes + bytes / 2) + 255) / 256 * 256;
  const auto total = static_cast<GLsizeiptr>(kSlots * slot_bytes_);
  glNamedBufferStorage(buffer_.get(), total, nullptr, kMapping);
  mapped_ = static_cast<unsigned char*>(glMapNamedBufferRange(buffer_.get(), 0, total, kMapping));
  slot_ = 0;
}

unsigned char* MappedRing::next(std::size_t bytes) {
  if (bytes > slot_bytes_ || !mapped_) {
    grow(bytes > 0 ? bytes : 1);
    return mapped_;
  }
  // Everything issued so far (the draws that read this slot) must finish before it is reused.
  if (fences_[slot_]) glDeleteSync(fences_[slot_]);
  fences_[slot_] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  slot_ = (slot_ + 1) % kSlots;
  if (GLsync fence = std::exchange(fences_[slot_], nullptr)) {
    const auto start = std::chrono::steady_clock::now();
    while (glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000) == GL_TIMEOUT_EXPIRED) {
    }
    glDeleteSync(fence);
    wait_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  return mapped_ + offset();
}

}  // namespace pyro::gpu
