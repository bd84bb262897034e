// The radix sort of the draw order against std::sort with the same comparator (back_to_front),
// element for element: random depths of both signs, many equal depths (ties broken by set and
// id), -0 beside +0, nearly sorted input (last frame's order with a few changes), a single key
// and none; and the depth mapping's order against the floats' own.
#include "systems/sorting/radix_sort.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace pyro {
namespace {

bool same(const SortKey& a, const SortKey& b) {
  return std::bit_cast<uint32_t>(a.depth) == std::bit_cast<uint32_t>(b.depth) && a.set == b.set &&
         a.id == b.id && a.particle == b.particle;
}

void expect_as_std_sort(std::vector<SortKey> keys, const char* what) {
  std::vector<SortKey> expected = keys;
  std::sort(expected.begin(), expected.end(), back_to_front);
  RadixScratch scratch;
  radix_sort_back_to_front(keys, scratch);
  ASSERT_EQ(keys.size(), expected.size()) << what;
  for (size_t i = 0; i < keys.size(); ++i)
    ASSERT_TRUE(same(keys[i], expected[i]))
        << what << ": at " << i << " depth " << keys[i].depth << " set " << keys[i].set << " id "
        << keys[i].id << ", expected depth " << expected[i].depth << " set " << expected[i].set
        << " id " << expected[i].id;
}

// `n` keys, set and id distinct per key (as in the engine), in shuffled order.
std::vector<SortKey> keys_with(size_t n, std::mt19937& random, float (*depth)(std::mt19937&)) {
  std::vector<SortKey> keys(n);
  for (size_t i = 0; i < n; ++i)
    keys[i] = {depth(random), static_cast<uint32_t>(i % 5), static_cast<uint32_t>(i / 5 * 7 + 3),
               static_cast<uint32_t>(i)};
  std::shuffle(keys.begin(), keys.end(), random);
  return keys;
}

TEST(RadixSort, EqualsStdSortOnRandomDepths) {
  std::mt19937 random(7);
  expect_as_std_sort(keys_with(100000, random, [](std::mt19937& r) {
                       return std::uniform_real_distribution<float>(-50.0f, 400.0f)(r);
                     }),
                     "random");
  expect_as_std_sort(keys_with(3000, random, [](std::mt19937& r) {
                       return std::ldexp(std::uniform_real_distribution<float>(-1.0f, 1.0f)(r),
                                         std::uniform_int_distribution<int>(-140, 120)(r));
                     }),
                     "magnitudes from denormal to 1e36");
}

TEST(RadixSort, EqualDepthsAreOrderedBySetThenId) {
  std::mt19937 random(11);
  expect_as_std_sort(keys_with(20000, random, [](std::mt19937& r) {
                       return static_cast<float>(std::uniform_int_distribution<int>(0, 6)(r));
                     }),
                     "seven depths");
  expect_as_std_sort(keys_with(5000, random, [](std::mt19937&) { return 2.5f; }), "one depth");
  expect_as_std_sort(keys_with(4000, random, [](std::mt19937& r) {
                       return std::uniform_int_distribution<int>(0, 1)(r) ? 0.0f : -0.0f;
                     }),
                     "-0 and +0, which compare equal");
}

TEST(RadixSort, NearlySortedInputAndSmallInputs) {
  std::mt19937 random(13);
  std::vector<SortKey> keys = keys_with(50000, random, [](std::mt19937& r) {
    return std::uniform_real_distribution<float>(1.0f, 30.0f)(r);
  });
  std::sort(keys.begin(), keys.end(), back_to_front);  // last frame's order...
  for (int k = 0; k < 200; ++k) {                      // ...then the particles moved a little
    SortKey& moved = keys[std::uniform_int_distribution<size_t>(0, keys.size() - 1)(random)];
    moved.depth += std::uniform_real_distribution<float>(-0.5f, 0.5f)(random);
  }
  expect_as_std_sort(keys, "nearly sorted");
  expect_as_std_sort({{1.0f, 0, 0, 0}}, "one key");
  expect_as_std_sort({}, "no key");
}

TEST(RadixSort, TheOrderIsTheSameForAnyNumberOfThreads) {
  // 300,000 keys split into as many chunks as the arena has threads (at least 65,536 each), with
  // only 40 distinct depths, so runs of equal depths cross every chunk boundary.
  std::mt19937 random(23);
  const std::vector<SortKey> keys = keys_with(300000, random, [](std::mt19937& r) {
    return static_cast<float>(std::uniform_int_distribution<int>(0, 39)(r)) * 0.25f;
  });
  std::vector<SortKey> expected = keys;
  std::sort(expected.begin(), expected.end(), back_to_front);
  for (const int threads : {1, 2, 3, 4}) {
    tbb::task_arena arena(threads);
    RadixScratch scratch;
    arena.execute([&] { radix_order_back_to_front(keys, scratch); });
    ASSERT_EQ(scratch.order.size(), keys.size());
    size_t wrong = 0;
    for (size_t i = 0; i < keys.size(); ++i) wrong += !same(keys[scratch.order[i]], expected[i]);
    EXPECT_EQ(wrong, 0u) << threads << " threads";
  }
}

TEST(RadixSort, ASelectionIsOrderedAsItsKeysAlone) {
  // The culled draw list sorts the keys some view can show: the order holds their indices into
  // the whole array, in the order std::sort gives those keys, with runs of equal depths.
  std::mt19937 random(11);
  std::vector<SortKey> keys = keys_with(200000, random, [](std::mt19937& r) {
    return float(std::uniform_int_distribution<int>(0, 5000)(r)) * 0.25f;
  });
  for (const int keep_one_in : {1, 3, 50}) {
    std::vector<uint32_t> selected;
    for (uint32_t i = 0; i < keys.size(); ++i)
      if (random() % keep_one_in == 0) selected.push_back(i);
    std::vector<uint32_t> expected = selected;
    std::sort(expected.begin(), expected.end(),
              [&](uint32_t a, uint32_t b) { return back_to_front(keys[a], keys[b]); });
    RadixScratch scratch;
    radix_order_back_to_front(keys, selected, scratch);
    EXPECT_EQ(scratch.order, expected) << "one in " << keep_one_in;
  }
  RadixScratch scratch;
  radix_order_back_to_front(keys, std::span<const uint32_t>(), scratch);
  EXPECT_TRUE(scratch.order.empty());  // an empty selection orders nothing
}

TEST(RadixSort, DepthBitsOrderLikeTheFloatsDescending) {
  const float values[] = {-std::numeric_limits<float>::infinity(), -1e30f, -2.0f, -1.0f,
                          -std::numeric_limits<float>::denorm_min(), 0.0f,
                          std::numeric_limits<float>::denorm_min(), 1e-30f, 1.0f, 2.0f, 1e30f,
                          std::numeric_limits<float>::infinity()};
  for (size_t i = 0; i + 1 < std::size(values); ++i)
    EXPECT_GT(descending_depth_bits(values[i]), descending_depth_bits(values[i + 1])) << values[i];
  EXPECT_EQ(descending_depth_bits(-0.0f), descending_depth_bits(0.0f));
}

}  // namespace
}  // namespace pyro
