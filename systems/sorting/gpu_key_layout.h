#pragma once
// The GPU's sort key (systems/gpu_sorting): 64 bits ordered ascending, the depth's
// descending_depth_bits (radix_sort.h) above a 32-bit tie-break that packs the set's rank among
// the sets (entity-index order) above the particle's id. Ascending order of that key is exactly
// back_to_front's (sort_key.h: farther first, then set, then id) as long as the rank and the
// largest id fit in 32 bits together: over 4 billion particles spawned by one set, or fewer by
// many sets, they do not, and the CPU orders the list instead.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>

#include "engine/particles/particle_pool.h"

namespace pyro {

struct GpuKeyLayout {
  uint32_t set_bits = 0;  // bits of the set's rank (0 for one set)
  uint32_t id_bits = 0;   // bits of the largest id any set has given
  bool fits() const { return set_bits + id_bits <= 32; }
  // The tie-break's significant bits, rounded up to the GPU's 4-bit digits.
  uint32_t tie_break_digits() const { return (set_bits + id_bits + 3) / 4; }
};

inline GpuKeyLayout gpu_key_layout(std::span<const ParticlePool* const> pools) {
  uint32_t largest_id = 0;
  for (const ParticlePool* p : pools)
    if (p->next_id() > 0) largest_id = std::max(largest_id, p->next_id() - 1);
  GpuKeyLayout layout;
  layout.set_bits = pools.size() > 1 ? uint32_t(std::bit_width(pools.size() - 1)) : 0u;
  layout.id_bits = uint32_t(std::bit_width(largest_id));
  return layout;
}

}  // namespace pyro
