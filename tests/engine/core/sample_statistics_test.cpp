// Nearest-rank percentiles (Hyndman & Fan definition 1) on samples whose answers are known.
#include <gtest/gtest.h>

#include "engine/core/sample_statistics.h"

namespace pyro {
namespace {

TEST(SampleStatistics, OneToTwentyInAnyOrder) {
  std::vector<double> v;
  for (int i = 20; i >= 1; --i) v.push_back(i);
  const SampleStatistics s = sample_statistics(v);
  EXPECT_EQ(s.count, 20u);
  EXPECT_DOUBLE_EQ(s.mean, 10.5);
  EXPECT_DOUBLE_EQ(s.median, 10.0);  // ceil(0.5 * 20) = 10th smallest
  EXPECT_DOUBLE_EQ(s.p95, 19.0);     // ceil(0.95 * 20) = 19th smallest
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 20.0);
}

TEST(SampleStatistics, SmallAndDegenerateSamples) {
  const SampleStatistics one = sample_statistics({7.0});
  EXPECT_DOUBLE_EQ(one.median, 7.0);
  EXPECT_DOUBLE_EQ(one.p95, 7.0);
  const SampleStatistics spike = sample_statistics({1, 1, 1, 1, 1, 1, 1, 1, 1, 100});
  EXPECT_DOUBLE_EQ(spike.p95, 100.0);  // ceil(9.5) = 10th: the spike
  EXPECT_DOUBLE_EQ(spike.median, 1.0);
  EXPECT_DOUBLE_EQ(spike.mean, 10.9);
  const SampleStatistics none = sample_statistics({});
  EXPECT_EQ(none.count, 0u);
  EXPECT_DOUBLE_EQ(none.p95, 0.0);
}

}  // namespace
}  // namespace pyro
