// Stability: particles at exactly equal depths keep one drawing order from frame to frame,
// whatever order their storage is in (swap-remove reorders pools every time a particle dies).
// The naive comparator, depth only, leaves equal keys in storage order: a frame whose storage
// was permuted draws them in another order, so overlapping splats swap and flicker.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "systems/sorting/depth_sort.h"

namespace pyro {
namespace {

// 60 particles on 3 planes of equal depth, in two sets; `permuted` stores them in reverse.
std::vector<SortKey> keys(bool permuted) {
  std::vector<SortKey> k;
  for (uint32_t set = 0; set < 2; ++set)
    for (uint32_t id = 0; id < 30; ++id)
      k.push_back({-1.0f - static_cast<float>(id % 3), set, id, static_cast<uint32_t>(k.size())});
  if (permuted) std::reverse(k.begin(), k.end());
  return k;
}

std::vector<std::pair<uint32_t, uint32_t>> drawn(const std::vector<SortKey>& k) {
  std::vector<std::pair<uint32_t, uint32_t>> out;
  for (const SortKey& s : k) out.push_back({s.set, s.id});
  return out;
}

TEST(StabilityEqualDepths, EngineOrderDoesNotDependOnStorageOrderNaiveDepthOnlyDoes) {
  // The naive method: sort by depth only (stable, so deterministic per storage order).
  auto naive = [](std::vector<SortKey> k) {
    std::stable_sort(k.begin(), k.end(), [](const SortKey& a, const SortKey& b) { return a.depth > b.depth; });
    return drawn(k);
  };
  EXPECT_NE(naive(keys(false)), naive(keys(true))) << "the naive comparator should swap ties";

  std::vector<SortKey> frame1 = keys(false), frame2 = keys(true);
  sort_back_to_front(frame1);
  sort_back_to_front(frame2);
  EXPECT_EQ(drawn(frame1), drawn(frame2));
  // And it is still back to front.
  for (size_t i = 1; i < frame1.size(); ++i) EXPECT_GE(frame1[i - 1].depth, frame1[i].depth);
}

}  // namespace
}  // namespace pyro
