// pyro chart integrators' data: the engine's exponential integrator stays bounded at every step,
// explicit Euler blows up exactly beyond its stability limit k dt > 2, and both converge to the
// chart's closed-form solution as the step shrinks (which checks the closed form too: two
// different methods meet it).
#include <gtest/gtest.h>

#include "tools/charts/charts.h"

namespace pyro {
namespace {

TEST(ChartIntegrators, EulerBlowsUpPastItsLimitExponentialHoldsAndBothConverge) {
  IntegratorChartOptions o;
  o.steps = {1.0 / 800, 1.0 / 400, 0.05, 0.125, 0.25, 0.5, 1.0};
  o.horizon = 2.0;
  o.drag = 10.0;
  o.particles = 4;
  const ChartTable t = chart_integrators(o);
  ASSERT_EQ(t.rows.size(), 14u);
  // Columns: dt, steps, k_dt, blew_up.
  for (size_t i = 0; i < 7; ++i) {
    const auto& exp_row = t.rows[i];
    const auto& euler_row = t.rows[7 + i];
    ASSERT_EQ(exp_row.group, "exponential");
    ASSERT_EQ(euler_row.group, "explicit Euler");
    EXPECT_EQ(exp_row.extra[3], 0.0) << exp_row.label;
    EXPECT_LT(exp_row.error, 1.0) << exp_row.label;
    const double k_dt = euler_row.extra[2];
    EXPECT_EQ(euler_row.extra[3], k_dt > 2.0 ? 1.0 : 0.0) << euler_row.label;
    if (k_dt > 2.0) {
      EXPECT_FALSE(euler_row.pareto);
    }
  }
  // First order: halving the step halves the error, and both meet the closed form.
  EXPECT_NEAR(t.rows[0].error / t.rows[1].error, 0.5, 0.05);
  EXPECT_NEAR(t.rows[7].error / t.rows[8].error, 0.5, 0.05);
  EXPECT_LT(t.rows[0].error, 2e-3);
  EXPECT_LT(t.rows[7].error, 2e-3);
  EXPECT_DOUBLE_EQ(t.summary["first_dt_blowing_up"]["explicit Euler"].get<double>(), 0.25);
  EXPECT_TRUE(t.summary["first_dt_blowing_up"]["exponential"].is_null());
}

}  // namespace
}  // namespace pyro
