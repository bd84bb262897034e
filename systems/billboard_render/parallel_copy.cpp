#include "systems/billboard_render/parallel_copy.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstring>

namespace pyro {

void parallel_copy(void* to, const void* from, std::size_t bytes) {
  constexpr std::size_t kPiece = std::size_t(1) << 20;
  auto* out = static_cast<unsigned char*>(to);
  const auto* in = static_cast<const unsigned char*>(from);
  if (bytes <= kPiece) {
    std::memcpy(out, in, bytes);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, (bytes + kPiece - 1) / kPiece),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t p = r.begin(); p < r.end(); ++p) {
                        const std::size_t begin = p * kPiece;
                        std::memcpy(out + begin, in + begin, std::min(kPiece, bytes - begin));
                      }
                    });
}

}  // namespace pyro
