#pragma once
// Sorting keys into the draw order (depth_sort.h's back_to_front: farther first, then set, then
// id) by a least-significant-digit radix sort of the depths, then std::sort of each run of equal
// depths by (set, id). The depth's float bits are mapped to an unsigned integer that orders like
// the float, descending (-0 taken as +0, which compares equal to it), so the order is exactly
// back_to_front's, ties and all: the result equals std::sort's with that comparator.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "systems/sorting/sort_key.h"

namespace pyro {

// The integer that orders like `depth`, farther (larger) first: a ascending-sort key.
uint32_t descending_depth_bits(float depth);

// Working space kept between frames (no allocation in steady state).
struct RadixScratch {
  std::vector<uint64_t> pairs, swap;  // (descending depth bits << 32 | key index)
  std::vector<uint32_t> order;        // the result of radix_order_back_to_front
};

// Bytes the draw order's sort holds per key: the key, its pair and the pair's swap buffer, the
// order's index.
inline constexpr std::size_t kSortBytesPerKey = sizeof(SortKey) + 2 * sizeof(uint64_t) + sizeof(uint32_t);

// The indices of `keys` in back_to_front order, into scratch.order: three passes of 11, 11 and
// 10 bits over 8-byte pairs (a pass whose digit is the same for every key is skipped), then the
// runs of equal depths ordered by (set, id). The keys themselves are not moved. Each pass is split
// over the calling arena's threads (chunks of at least 65,536 pairs, each counted and scattered
// by its own task); the order is the same for any number of threads.
void radix_order_back_to_front(const std::vector<SortKey>& keys, RadixScratch& scratch);

// The same for the keys at `selected` alone (indices into `keys`; none when empty):
// scratch.order holds those indices in back_to_front order.
void radix_order_back_to_front(const std::vector<SortKey>& keys, std::span<const uint32_t> selected,
                               RadixScratch& scratch);

// Sorts `keys` with back_to_front (radix_order_back_to_front, then the keys gathered).
void radix_sort_back_to_front(std::vector<SortKey>& keys, RadixScratch& scratch);

}  // namespace pyro
