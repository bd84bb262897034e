// pyro chart footprint's data: each quadrature rule converges at its order (trapezoid and
// midpoint h^2, Simpson h^4), and with enough intervals the error falls as the table's node
// spacing squared.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "tools/charts/charts.h"

namespace pyro {
namespace {

TEST(ChartFootprint, EachRuleConvergesAtItsOrderAndErrorFallsWithTableSize) {
  FootprintChartOptions o;
  o.sizes = {16, 32, 64};
  o.intervals = {8, 16, 32};
  o.sample_grid = 121;
  o.repeats = 1;
  const ChartTable t = chart_footprint(o);
  ASSERT_EQ(t.rows.size(), 3u * 3u * 3u);
  // Column order: size, intervals, quadrature_error, sampled_error, order.
  const std::map<std::string, double> expected_order = {{"trapezoid", 2.0}, {"simpson", 4.0}, {"midpoint", 2.0}};
  std::map<std::string, std::map<int, double>> error_at_size;  // rule -> size -> error (K = 32)
  for (const auto& r : t.rows) {
    const int size = static_cast<int>(r.extra[0]), k = static_cast<int>(r.extra[1]);
    if (k == 16) {
      EXPECT_NEAR(r.extra[4], expected_order.at(r.group), 0.25) << r.label;
    }
    if (k == 32) {
      EXPECT_TRUE(std::isnan(r.extra[4])) << r.label;
      error_at_size[r.group][size] = r.error;
    }
    EXPECT_GT(r.time, 0.0);
  }
  EXPECT_NEAR(t.summary["quadrature_order"]["simpson"].get<double>(), 4.0, 0.25);
  for (const auto& [rule, errors] : error_at_size) {
    // Halving the node spacing divides the (reconstruction-dominated) error by about 4.
    EXPECT_GT(errors.at(16) / errors.at(32), 3.0) << rule;
    EXPECT_GT(errors.at(32) / errors.at(64), 3.0) << rule;
  }
}

}  // namespace
}  // namespace pyro
