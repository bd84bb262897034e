// pyro bench sort's result: the three sorts agree on the order, and each was timed.
#include "tools/bench/bench_sort.h"

#include <gtest/gtest.h>

namespace pyro {
namespace {

TEST(BenchSort, TheThreeSortsAgree) {
  const nlohmann::json r = bench_sort(20000, 3);
  EXPECT_EQ(r["count"], 20000);
  EXPECT_TRUE(r["same_order"].get<bool>());
  const double radix = r["radix_ms"], standard = r["std_sort_ms"], parallel = r["parallel_sort_ms"];
  ASSERT_GT(radix, 0.0);
  ASSERT_GT(standard, 0.0);
  ASSERT_GT(parallel, 0.0);
}

}  // namespace
}  // namespace pyro
