#include "engine/math/tabulated_erf.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pyro {
namespace {

// Against std::erf on a sweep finer than the table and off its nodes: within the interpolation
// bound h^2/8 max|erf''| ~ 1.1e-7, odd, and +-1 beyond the table.
TEST(TabulatedErf, FollowsStdErfWithinTheInterpolationBound) {
  double worst = 0.0;
  for (int k = -600000; k <= 600000; ++k) {
    const double x = k * 1e-5 + 3.3e-7;
    worst = std::max(worst, std::abs(tabulated_erf(x) - std::erf(x)));
  }
  EXPECT_LT(worst, 1.2e-7);
  EXPECT_GT(worst, 1e-9);  // a table, not std::erf itself
  EXPECT_NEAR(tabulated_erf(0.731), -tabulated_erf(-0.731), 1e-12);
  EXPECT_EQ(tabulated_erf(4.0), 1.0);
  EXPECT_EQ(tabulated_erf(-9.0), -1.0);
  EXPECT_TRUE(std::isnan(tabulated_erf(std::nan(""))));
}

}  // namespace
}  // namespace pyro
