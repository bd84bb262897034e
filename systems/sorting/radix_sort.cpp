#include "systems/sorting/radix_sort.h"

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

// One stable counting pass over the digit (pair >> (32 + shift)) & mask, or none (false) when
// every pair has the same digit.
bool radix_pass(const std::vector<uint64_t>& from, std::vector<uint64_t>& to, int shift,
                uint32_t mask) {
  std::array<uint32_t, 2048> count{};
  for (uint64_t p : from) ++count[(p >> (32 + shift)) & mask];
  if (std::any_of(count.begin(), count.end(), [&](uint32_t c) { return c == from.size(); }))
    return false;
  uint32_t sum = 0;
  for (uint32_t& c : count) {
    const uint32_t here = c;
    c = sum;
    sum += here;
  }
  for (uint64_t p : from) to[count[(p >> (32 + shift)) & mask]++] = p;
  return true;
}

}  // namespace

void radix_order_back_to_front(const std::vector<SortKey>& keys, RadixScratch& s) {
  const size_t n = keys.size();
  s.pairs.resize(n);
  s.swap.resize(n);
  for (size_t i = 0; i < n; ++i)
    s.pairs[i] = uint64_t(descending_depth_bits(keys[i].depth)) << 32 | uint32_t(i);
  constexpr std::array<std::pair<int, uint32_t>, 3> digits = {
      {{0, 0x7ffu}, {11, 0x7ffu}, {22, 0x3ffu}}};
  for (const auto& [shift, mask] : digits)
    if (radix_pass(s.pairs, s.swap, shift, mask)) s.pairs.swap(s.swap);
  s.order.resize(n);
  for (size_t i = 0; i < n; ++i) s.order[i] = uint32_t(s.pairs[i]);
  // Equal depths (bit for bit, -0 as +0): the tie-breaks, (set, id).
  for (size_t begin = 0; begin < n;) {
    size_t end = begin + 1;
    while (end < n && (s.pairs[end] >> 32) == (s.pairs[begin] >> 32)) ++end;
    if (end - begin > 1)
      std::sort(s.order.begin() + begin, s.order.begin() + end,
                [&](uint32_t a, uint32_t b) { return back_to_front(keys[a], keys[b]); });
    begin = end;
  }
}

void radix_sort_back_to_front(std::vector<SortKey>& keys, RadixScratch& s) {
  radix_order_back_to_front(keys, s);
  std::vector<SortKey> sorted(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) sorted[i] = keys[s.order[i]];
  keys.swap(sorted);
}

}  // namespace pyro
