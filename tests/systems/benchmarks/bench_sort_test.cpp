// pyro bench sort's result: the three sorts agree, the ratios are the timings' own, and the
// fields the docs name are there.
#include "systems/benchmarks/bench_sort.h"

#include <gtest/gtest.h>

namespace pyro {
namespace {

TEST(BenchSort, TheThreeSortsAgreeAndTheRatiosAreTheTimings) {
  const nlohmann::json r = bench_sort(20000, 3);
  EXPECT_EQ(r["count"], 20000);
  EXPECT_TRUE(r["same_order"].get<bool>());
  const double radix = r["radix_ms"], standard = r["std_sort_ms"], parallel = r["parallel_sort_ms"];
  ASSERT_GT(radix, 0.0);
  ASSERT_GT(standard, 0.0);
  ASSERT_GT(parallel, 0.0);
  EXPECT_DOUBLE_EQ(r["radix_over_std_sort"].get<double>(), radix / standard);
  EXPECT_DOUBLE_EQ(r["radix_over_parallel_sort"].get<double>(), radix / parallel);
  EXPECT_EQ(r["bytes_per_key"], 36);
}

}  // namespace
}  // namespace pyro
