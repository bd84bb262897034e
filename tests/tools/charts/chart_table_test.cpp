// The Pareto front of a chart (tools/charts/chart_table.h) and its CSV.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "engine/core/rng.h"
#include "tools/charts/chart_table.h"

namespace pyro {
namespace {

bool dominates(const ChartTable::Row& a, const ChartTable::Row& b) {
  return a.time <= b.time && a.error <= b.error && (a.time < b.time || a.error < b.error);
}

TEST(ChartTable, ParetoFrontIsExactlyTheNonDominatedPoints) {
  ChartTable t;
  Rng rng(7);
  for (int i = 0; i < 200; ++i) {
    ChartTable::Row r;
    r.time = rng.uniform(0.0f, 10.0f);
    r.error = std::exp(rng.uniform(-8.0f, 0.0f));
    r.front = i % 2 ? "a" : "b";
    t.rows.push_back(r);
  }
  t.rows[3].usable = false;
  t.rows[3].time = t.rows[3].error = 0.0;  // would dominate everything if it counted
  t.rows[5].error = std::numeric_limits<double>::infinity();
  mark_pareto_front(t);
  int on_front = 0;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const auto& r = t.rows[i];
    bool dominated = false;
    for (size_t j = 0; j < t.rows.size(); ++j)
      if (j != 3 && j != 5 && t.rows[j].front == r.front && dominates(t.rows[j], r)) dominated = true;
    if (i == 3 || i == 5) {
      EXPECT_FALSE(r.pareto) << i;
      continue;
    }
    EXPECT_EQ(r.pareto, !dominated) << i;
    on_front += r.pareto;
  }
  EXPECT_GE(on_front, 2);  // at least one per front key
}

TEST(ChartTable, CsvHasTheCommentsHeaderAndOneLinePerRow) {
  ChartTable t;
  t.title = "T";
  t.x_label = "ms";
  t.y_label = "rmse";
  t.ground_truth = "closed form";
  t.notes = {"n1"};
  t.extra_columns = {"size"};
  t.rows.push_back({"a,b", "g", 1.5, 0.25, {8.0}, false, true, ""});
  t.rows.push_back({"c", "g", 2.0, 0.125, {16.0}, false, false, "k"});
  mark_pareto_front(t);
  std::istringstream in(chart_csv(t));
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 8u);
  EXPECT_EQ(lines[0], "# title: T");
  EXPECT_EQ(lines[3], "# ground truth: closed form");
  EXPECT_EQ(lines[5], "label,group,time,error,size,pareto,usable,front");
  EXPECT_EQ(lines[6], "\"a,b\",g,1.5,0.25,8,1,1,");
  EXPECT_EQ(lines[7], "c,g,2,0.125,16,0,0,k");
}

}  // namespace
}  // namespace pyro
