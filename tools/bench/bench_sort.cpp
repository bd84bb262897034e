#include "tools/bench/bench_sort.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <vector>

#include "systems/sorting/radix_sort.h"

namespace pyro {

namespace {

std::vector<SortKey> engine_like_keys(std::size_t count) {
  std::mt19937 random(20061);
  std::uniform_real_distribution<float> depth(1.0f, 100.0f);
  std::vector<uint32_t> ids(count);
  for (std::size_t i = 0; i < count; ++i) ids[i] = static_cast<uint32_t>(i);
  std::shuffle(ids.begin(), ids.end(), random);  // a pool's ids after births and deaths
  std::vector<SortKey> keys(count);
  for (std::size_t i = 0; i < count; ++i)
    keys[i] = {depth(random), 0u, ids[i], static_cast<uint32_t>(i)};
  return keys;
}

// Milliseconds of `sort` on a fresh copy of `keys`, the median of `repeats`; the last result.
template <class Sort>
double median_ms(const std::vector<SortKey>& keys, int repeats, Sort sort,
                 std::vector<SortKey>* result) {
  std::vector<double> ms;
  for (int r = 0; r < repeats; ++r) {
    std::vector<SortKey> copy = keys;
    const auto t0 = std::chrono::steady_clock::now();
    sort(copy);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (r + 1 == repeats) *result = std::move(copy);
  }
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  return ms[ms.size() / 2];
}

}  // namespace

nlohmann::json bench_sort(std::size_t count, int repeats) {
  const std::vector<SortKey> keys = engine_like_keys(count);
  RadixScratch scratch;  // kept between frames by the sorting system: warm here too
  radix_order_back_to_front(keys, scratch);
  std::vector<SortKey> unused, by_std, by_parallel;
  // The draw order as the sorting system takes it: the keys' indices (radix_sort.h).
  const double radix = median_ms(keys, repeats, [&](std::vector<SortKey>& k) {
    radix_order_back_to_front(k, scratch);
  }, &unused);
  std::vector<SortKey> by_radix(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) by_radix[i] = keys[scratch.order[i]];
  const double standard = median_ms(keys, repeats, [](std::vector<SortKey>& k) {
    std::sort(k.begin(), k.end(), back_to_front);
  }, &by_std);
  const double parallel = median_ms(keys, repeats, [](std::vector<SortKey>& k) {
    tbb::parallel_sort(k.begin(), k.end(), back_to_front);
  }, &by_parallel);
  auto same = [](const std::vector<SortKey>& a, const std::vector<SortKey>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const SortKey& x, const SortKey& y) {
      return x.depth == y.depth && x.set == y.set && x.id == y.id && x.particle == y.particle;
    });
  };
  return {{"count", count},
          {"repeats", repeats},
          {"radix_ms", radix},
          {"std_sort_ms", standard},
          {"parallel_sort_ms", parallel},
          {"radix_over_std_sort", standard > 0.0 ? radix / standard : 0.0},
          {"radix_over_parallel_sort", parallel > 0.0 ? radix / parallel : 0.0},
          {"bytes_per_key", kSortBytesPerKey},
          {"same_order", same(by_radix, by_std) && same(by_parallel, by_std)}};
}

}  // namespace pyro
