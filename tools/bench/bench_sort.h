#pragma once
// The draw order's sort (systems/sorting/radix_sort.h: the keys' indices in draw order, as the
// sorting system takes it) against std::sort and tbb::parallel_sort of the same keys with the
// same comparator, in one run: `count` keys as the sorting system
// makes them (view depths in [1, 100), one set, distinct ids, in storage order), each method on
// the same shuffled copy, the median of `repeats` timings. See bench_sort.cpp.
#include <cstddef>
#include <nlohmann/json.hpp>

namespace pyro {

// Returns {"count", "repeats", "radix_ms", "std_sort_ms", "parallel_sort_ms",
// "radix_over_std_sort", "radix_over_parallel_sort", "bytes_per_key", "same_order"}.
nlohmann::json bench_sort(std::size_t count, int repeats);

}  // namespace pyro
