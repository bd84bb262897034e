// The profiler panel's series: samples kept for the last window of seconds, in time order.
#include "tools/viewer/frame_time_history.h"

#include <gtest/gtest.h>

namespace pyro {
namespace {

TEST(FrameTimeHistory, KeepsTheLastWindowOfSamplesPerSeries) {
  FrameTimeHistory h(2.0);
  for (int i = 0; i <= 50; ++i) {  // 0.1 s apart, 0..5 s
    h.add("render", 0.1 * i, double(i));
    if (i % 2 == 0) h.add("sort", 0.1 * i, 1.0);
    h.trim(0.1 * i);
  }
  // At t = 5 the window [3, 5] holds samples 30..50 of "render".
  const std::vector<float> v = h.values("render");
  ASSERT_EQ(v.size(), 21u);
  EXPECT_EQ(v.front(), 30.0f);
  EXPECT_EQ(v.back(), 50.0f);
  EXPECT_DOUBLE_EQ(h.mean("render"), 40.0);  // the mean of 30..50
  EXPECT_DOUBLE_EQ(h.max("render"), 50.0);
  EXPECT_EQ(h.values("sort").size(), 11u);  // every other sample
  EXPECT_EQ(h.names(), (std::vector<std::string>{"render", "sort"}));
}

TEST(FrameTimeHistory, ForgetsSeriesThatStoppedReporting) {
  FrameTimeHistory h(1.0);
  h.add("gone", 0.0, 3.0);
  h.add("kept", 0.5, 1.0);
  h.trim(2.0);
  EXPECT_TRUE(h.values("gone").empty());
  EXPECT_TRUE(h.values("kept").empty());
  EXPECT_TRUE(h.names().empty());
  EXPECT_EQ(h.mean("gone"), 0.0);
  EXPECT_EQ(h.max("unknown"), 0.0);
}

}  // namespace
}  // namespace pyro
