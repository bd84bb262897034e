#pragma once
// A particle's place in the draw order (depth_sort.h): its depth for the view, and the
// tie-breaks that make the order a strict total order, so equal depths never swap between
// frames or runs.
#include <cstdint>

namespace pyro {

struct SortKey {
  float depth;
  uint32_t set;       // tie-break 1: the owning entity's index
  uint32_t id;        // tie-break 2: the particle's id within its set
  uint32_t particle;  // where to read it from
};

// Strict weak order: farther first, then set, then id.
inline bool back_to_front(const SortKey& a, const SortKey& b) {
  if (a.depth != b.depth) return a.depth > b.depth;
  if (a.set != b.set) return a.set < b.set;
  return a.id < b.id;
}

}  // namespace pyro
