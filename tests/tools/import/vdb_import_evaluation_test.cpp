// The import's error from every side: the views look at the grid's centre from seven distinct
// directions at one distance (and from inside when the grid is large enough); an import refined
// to a reachable target meets it on every view; an unreachable target ends with target_met false,
// a reason, and the best error it reached, never a silent miss.
#include "tools/import/fitted_import.h"
#include "tools/import/vdb_import_evaluation.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "systems/runtime/cloud_import/grid_framing.h"

namespace pyro {
namespace {

// A soft ball of density, n voxels a side.
DenseGrid ball_grid(int n) {
  DenseGrid g;
  g.dims = {n, n, n};
  g.values.resize(size_t(n) * n * n);
  const double c = 0.5 * (n - 1), r2 = 0.2 * n * n;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double d2 = (x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c);
        g.values[(size_t(z) * n + y) * n + x] = d2 < r2 ? float(1.0 - d2 / r2) : 0.0f;
      }
  g.index_to_world = glm::dmat4(1.0);
  for (float v : g.values) g.active_voxels += v > 0.0f;
  g.max_value = 1.0f;
  return g;
}

TEST(VdbImportViews, SevenDirectionsAtOneDistanceAndOneInside) {
  const DenseGrid g = ball_grid(16);
  const std::vector<CameraDescription> views = views_around(g);
  ASSERT_EQ(views.size(), 7u);
  const glm::vec3 centre = views[0].target;
  const float distance = glm::length(views[0].position - centre);
  for (size_t i = 0; i < views.size(); ++i) {
    EXPECT_EQ(views[i].target, centre) << i;
    EXPECT_NEAR(glm::length(views[i].position - centre), distance, 1e-4f * distance) << i;
    const glm::vec3 dir = glm::normalize(views[i].position - centre);
    EXPECT_LT(std::abs(glm::dot(dir, glm::normalize(views[i].up))), 0.99f) << i;  // up never along the view
    for (size_t j = 0; j < i; ++j)
      EXPECT_LT(glm::dot(dir, glm::normalize(views[j].position - centre)), 0.99f) << i << " " << j;
  }
  ASSERT_TRUE(view_inside(g).has_value());
  EXPECT_EQ(view_inside(g)->position, centre);
  EXPECT_FALSE(view_inside(ball_grid(6)).has_value());  // too small to stand inside
}

TEST(VdbImportViews, AReachableTargetIsMetOnEveryView) {
  const DenseGrid g = ball_grid(16);
  const VdbImportReference reference = make_vdb_import_reference(g, 48, 48, true);
  ASSERT_EQ(reference.view_images.size(), 7u);
  const FittedImport fit = import_to_target(g, 0.05, reference);
  EXPECT_TRUE(fit.target_met) << fit.reason;
  EXPECT_TRUE(fit.reason.empty());
  ASSERT_EQ(fit.best.view_rmse.size(), 7u);
  double sum = 0.0;
  for (double e : fit.best.view_rmse) {
    EXPECT_LE(e, 0.05);
    EXPECT_LE(e, fit.best.rmse_views_max);
    sum += e;
  }
  EXPECT_NEAR(fit.best.rmse_views_mean, sum / 7.0, 1e-12);
  EXPECT_DOUBLE_EQ(fit.best.view_rmse[0], fit.best.rmse);  // the framing view comes first
  EXPECT_TRUE(std::isfinite(fit.best.rmse_inside));
}

TEST(VdbImportViews, AnUnreachableTargetIsSaidWithTheBestReached) {
  const DenseGrid g = ball_grid(16);
  const VdbImportReference reference = make_vdb_import_reference(g, 48, 48, true);
  FitSchedule schedule;
  schedule.max_rounds = 3;
  schedule.starts = 2;
  const FittedImport fit = import_to_target(g, 1e-5, reference, schedule);
  EXPECT_FALSE(fit.target_met);
  EXPECT_FALSE(fit.reason.empty());
  EXPECT_GT(fit.best.rmse_views_max, 1e-5);
  // At most three rounds in each of the two starts, and the second start counted.
  EXPECT_LE(fit.refinements, 3 + 1 + 3);
  EXPECT_EQ(fit.best.fitted.size(), fit.best.report.particles);
}

}  // namespace
}  // namespace pyro
