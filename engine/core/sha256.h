#pragma once
// SHA-256 (FIPS 180-4): the content digests that key a run's identity (what a frame depends on),
// the asset digest cache and the quality cache. Written here from the standard; checked against
// its published test vectors (tests/engine/core/sha256_test.cpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace pyro {

class Sha256 {
 public:
  Sha256();
  void update(const void* data, size_t size);
  void update(std::string_view bytes) { update(bytes.data(), bytes.size()); }
  // The digest as 64 lowercase hex digits. The object is spent afterwards.
  std::string hex_digest();

 private:
  void compress(const uint8_t* block);
  std::array<uint32_t, 8> state_;
  std::array<uint8_t, 64> buffer_{};
  size_t buffered_ = 0;
  uint64_t total_bytes_ = 0;
};

// The hex digest of `bytes` in one call.
std::string sha256_hex(std::string_view bytes);

}  // namespace pyro
