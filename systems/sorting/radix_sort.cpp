#include "systems/sorting/radix_sort.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <bit>

namespace pyro {

uint32_t descending_depth_bits(float depth) {
  if (depth == 0.0f) depth = 0.0f;  // -0 == +0: one key for both
  const uint32_t bits = std::bit_cast<uint32_t>(depth);
  // Ascending float order as unsigned: negative floats reversed, positive ones above them.
  const uint32_t ascending = (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
  return ~ascending;
}

namespace {

constexpr int kDigitBits = 11;
constexpr size_t kBuckets = size_t(1) << kDigitBits;
// Pairs per chunk at least: below this, splitting costs more than it gains.
constexpr size_t kMinChunk = 65536;

using Histogram = std::array<uint32_t, kBuckets>;

// The chunks of [0, n) the passes split the pairs into: as many as the arena has threads, each
// at least kMinChunk long. The result does not depend on the split (each pass is stable).
std::vector<std::pair<size_t, size_t>> chunks_of(size_t n) {
  const size_t threads = static_cast<size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
  const size_t count = std::clamp<size_t>(n / kMinChunk, 1, threads);
  std::vector<std::pair<size_t, size_t>> chunks(count);
  for (size_t c = 0; c < count; ++c) chunks[c] = {n * c / count, n * (c + 1) / count};
  return chunks;
}

// One stable counting pass over the digit (pair >> (32 + shift)) & mask, each chunk counted and
// scattered by its own task (chunk c's pairs of a digit go after chunk c - 1's), or none (false)
// when every pair has the same digit.
bool radix_pass(const std::vector<uint64_t>& from, std::vector<uint64_t>& to, int shift,
                uint32_t mask, const std::vector<std::pair<size_t, size_t>>& chunks,
                std::vector<Histogram>& counts) {
  const int digit_shift = 32 + shift;
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t c) {
    Histogram& count = counts[c];
    count.fill(0);
    for (size_t i = chunks[c].first; i < chunks[c].second; ++i) ++count[(from[i] >> digit_shift) & mask];
  });
  uint32_t sum = 0;
  for (size_t b = 0; b <= mask; ++b) {
    uint32_t in_bucket = 0;
    for (Histogram& count : counts) in_bucket += count[b];
    if (in_bucket == from.size()) return false;
    for (Histogram& count : counts) {
      const uint32_t here = count[b];
      count[b] = sum;
      sum += here;
    }
  }
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t c) {
    Histogram& next = counts[c];
    for (size_t i = chunks[c].first; i < chunks[c].second; ++i) {
      const uint64_t p = from[i];
      to[next[(p >> digit_shift) & mask]++] = p;
    }
  });
  return true;
}

// Runs of equal depths (bit for bit, -0 as +0) in [begin, end) ordered by the tie-breaks, (set,
// id). A run that crosses `end` is left to the chunk it starts in.
void order_ties(const std::vector<SortKey>& keys, RadixScratch& s, size_t begin, size_t end) {
  const size_t n = s.pairs.size();
  while (begin > 0 && begin < n && (s.pairs[begin] >> 32) == (s.pairs[begin - 1] >> 32)) ++begin;
  while (begin < end) {
    size_t run_end = begin + 1;
    while (run_end < n && (s.pairs[run_end] >> 32) == (s.pairs[begin] >> 32)) ++run_end;
    if (run_end - begin > 1)
      std::sort(s.order.begin() + begin, s.order.begin() + run_end,
                [&](uint32_t a, uint32_t b) { return back_to_front(keys[a], keys[b]); });
    begin = run_end;
  }
}

// The order of keys[selected[i]] for i < n, or of keys[0 .. n) when `selected` is null.
void order_selected(const std::vector<SortKey>& keys, const uint32_t* selected, size_t n,
                    RadixScratch& s) {
  const bool all = selected == nullptr;
  // Room for every key: a frame that selects more than the last does not reallocate.
  for (std::vector<uint64_t>* v : {&s.pairs, &s.swap}) {
    v->reserve(keys.size());
    v->resize(n);
  }
  s.order.reserve(keys.size());
  s.order.resize(n);
  const std::vector<std::pair<size_t, size_t>> chunks = chunks_of(n);
  std::vector<Histogram> counts(chunks.size());
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t c) {
    for (size_t i = chunks[c].first; i < chunks[c].second; ++i) {
      const uint32_t k = all ? uint32_t(i) : selected[i];
      s.pairs[i] = uint64_t(descending_depth_bits(keys[k].depth)) << 32 | k;
    }
  });
  constexpr std::array<std::pair<int, uint32_t>, 3> digits = {
      {{0, 0x7ffu}, {11, 0x7ffu}, {22, 0x3ffu}}};
  for (const auto& [shift, mask] : digits)
    if (radix_pass(s.pairs, s.swap, shift, mask, chunks, counts)) s.pairs.swap(s.swap);
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t c) {
    for (size_t i = chunks[c].first; i < chunks[c].second; ++i) s.order[i] = uint32_t(s.pairs[i]);
  });
  // Equal depths: the tie-breaks, each chunk's runs by its own task.
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t c) {
    order_ties(keys, s, chunks[c].first, chunks[c].second);
  });
}

}  // namespace

void radix_order_back_to_front(const std::vector<SortKey>& keys, RadixScratch& s) {
  order_selected(keys, nullptr, keys.size(), s);
}

void radix_order_back_to_front(const std::vector<SortKey>& keys, std::span<const uint32_t> selected,
                               RadixScratch& s) {
  order_selected(keys, selected.data(), selected.size(), s);
}

void radix_sort_back_to_front(std::vector<SortKey>& keys, RadixScratch& s) {
  radix_order_back_to_front(keys, s);
  std::vector<SortKey> sorted(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) sorted[i] = keys[s.order[i]];
  keys.swap(sorted);
}

}  // namespace pyro
