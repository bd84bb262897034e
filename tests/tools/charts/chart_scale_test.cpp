// pyro chart scale's data: one CSV row per count with the benchmark's own figures, the slopes
// in comment lines, the scene named in the title.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "tools/charts/charts.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(ChartScale, OneRowPerCountWithTheBenchmarksFigures) {
  ScaleChartOptions o;
  o.scene = test::scene_path("clouds.json");
  o.counts = {2000, 6000};
  o.frames = 1;
  o.width = 48;
  o.height = 32;
  const ScaleChart chart = chart_scale(o);
  std::istringstream lines(chart.csv);
  std::vector<std::string> comments, rows;
  for (std::string line; std::getline(lines, line);) (line.rfind('#', 0) == 0 ? comments : rows).push_back(line);
  ASSERT_EQ(rows.size(), 3u);  // the header and one row per count
  EXPECT_EQ(rows[0].rfind("particles,ms_per_frame,cpu_ms_per_frame,", 0), 0u);
  EXPECT_EQ(rows[1].rfind("2000,", 0), 0u);
  EXPECT_EQ(rows[2].rfind("6000,", 0), 0u);
  ASSERT_EQ(chart.bench["counts"].size(), 2u);
  std::ostringstream cpu;
  cpu.precision(17);
  cpu << chart.bench["counts"][1]["cpu_ms_per_frame"].get<double>();
  EXPECT_NE(rows[2].find("," + cpu.str() + ","), std::string::npos) << rows[2];
  EXPECT_NE(comments.at(0).find("clouds.json"), std::string::npos);
  bool slope_line = false;
  for (const std::string& c : comments) slope_line |= c.rfind("# cpu_slope: none", 0) == 0;
  EXPECT_TRUE(slope_line);  // no count from 1e5 to 2e6, so no slope
}

}  // namespace
}  // namespace pyro
