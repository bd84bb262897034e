// The charts that render (layer-resolution, billboard-modes, particle-budget), at tiny sizes:
// invariants of their data, not their values.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "engine/core/content_path.h"
#include "tools/charts/charts.h"

namespace pyro {
namespace {

TEST(ChartLayerResolution, ErrorIsZeroAtFullResolutionAndGrowsAsLayersShrink) {
  LayerResolutionChartOptions o;
  o.width = o.height = 64;
  o.frames = 4;
  o.error_frames = 2;
  const ChartTable t = chart_layer_resolution(o);
  ASSERT_EQ(t.rows.size(), 16u);  // 2 views x 2 methods x 4 scales
  for (size_t m = 0; m < 4; ++m) {
    const auto* rows = &t.rows[4 * m];
    EXPECT_EQ(rows[0].extra[0], 1.0);
    EXPECT_EQ(rows[0].error, 0.0) << rows[0].label;  // its own ground truth
    EXPECT_GT(rows[1].error, 0.0) << rows[1].label;
    EXPECT_GT(rows[3].error, rows[1].error) << rows[3].label;  // 1/8 worse than 1/2
    for (int s = 0; s < 4; ++s) EXPECT_GT(rows[s].time, 0.0);
    // edge_error and halo (extra columns 3 and 4): none against its own ground truth.
    EXPECT_EQ(rows[0].extra[3], 0.0) << rows[0].label;
    EXPECT_EQ(rows[0].extra[4], 0.0) << rows[0].label;
    EXPECT_GT(rows[3].extra[3], 0.0) << rows[3].label;
  }
  EXPECT_EQ(t.rows[0].group, "depth-aware (explosion)");
  EXPECT_EQ(t.rows[4].group, "bilinear (explosion)");
  EXPECT_EQ(t.rows[8].group, "depth-aware (explosion_behind_tower)");
  // One Pareto front per view.
  EXPECT_EQ(t.rows[0].front, "explosion");
  EXPECT_EQ(t.rows[15].front, "explosion_behind_tower");
}

TEST(ChartBillboardModes, ThreeModesPerSceneWithinTheAccuracyBar) {
  BillboardModesChartOptions o;
  o.scenes = {content_path("scenes/fog.json")};
  o.width = 64;
  o.height = 48;
  o.frames = 1;
  const ChartTable t = chart_billboard_modes(o);
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0].group, "viewplane");
  EXPECT_EQ(t.rows[1].group, "viewpoint");
  EXPECT_EQ(t.rows[2].group, "spherical");
  for (const auto& r : t.rows) {
    EXPECT_GT(r.extra[0], 100.0) << r.label;  // the fog's particles reached the reference
    EXPECT_GT(r.error, 0.0) << r.label;
    EXPECT_LT(r.error, 0.03) << r.label;  // the project's image accuracy bar
  }
}

// The fitted cloud has no isotropic splats: sunlight at the vertices would chart its frames twice.
TEST(ChartShadows, ScenesWithoutSplatsAreNotChartedTwice) {
  ShadowsChartOptions o;
  o.scenes = {content_path("scenes/cloud_fitted.json")};
  o.map_sizes = {8};
  o.width = 32;
  o.height = 24;
  o.frames = 1;
  const ChartTable t = chart_shadows(o);
  ASSERT_EQ(t.rows.size(), 3u);  // none, rays, the map
  for (const ChartTable::Row& r : t.rows) EXPECT_EQ(r.label.find("vertices"), std::string::npos) << r.label;
}

TEST(ChartShadows, EverySettingAgainstTheReferenceWithShadowsHelp) {
  ShadowsChartOptions o;
  o.scenes = {content_path("scenes/clouds.json")};
  o.map_sizes = {8, 64};
  o.width = 64;
  o.height = 48;
  o.frames = 1;
  const ChartTable t = chart_shadows(o);
  ASSERT_EQ(t.rows.size(), 7u);  // none, rays, two maps; rays and the maps with sunlight at vertices
  EXPECT_EQ(t.rows[0].group, "none");
  EXPECT_EQ(t.rows[1].group, "rays");
  EXPECT_EQ(t.rows[3].label, "clouds map 64x32");
  EXPECT_EQ(t.rows[6].label, "clouds map 64x32 sunlight at vertices");
  EXPECT_EQ(t.rows[6].group, "map (sunlight at vertices)");
  for (const auto& r : t.rows) {
    EXPECT_EQ(r.extra[1], 1500.0) << r.label;  // the clouds' particles
    EXPECT_GT(r.time, 0.0) << r.label;
  }
  // Shadows bring the frame closer to the reference; the finer map closer than the coarse one.
  EXPECT_LT(t.rows[1].error, t.rows[0].error);
  EXPECT_LT(t.rows[3].error, t.rows[2].error);
  EXPECT_LT(t.rows[3].error, 0.03);  // the project's image accuracy bar
  EXPECT_LT(t.rows[6].error, 0.03);
  EXPECT_GT(t.rows[1].extra[0], t.rows[0].extra[0]);  // rays cost the light phase more than none
}

TEST(ChartShadows, AgainstDensityTheErrorGrowsWithoutShadowsAndTheMapLeavesTheTargetLast) {
  ShadowDensityChartOptions o;
  o.densities = {0.4, 1.0};
  o.map_sizes = {64};
  o.width = 64;
  o.height = 36;
  o.frames = 1;
  const ChartTable t = chart_shadow_density(o);
  ASSERT_EQ(t.rows.size(), 6u);  // none, rays, the map at each density
  EXPECT_EQ(t.rows[2].label, "rho 0.4 map 64x32");
  EXPECT_EQ(t.rows[3].front, "rho 1");
  EXPECT_NEAR(t.rows[3].extra[1], -std::log(1e-12), 1e-6);  // tau0 as the splats clamp it
  EXPECT_NEAR(t.rows[0].extra[1], -std::log(0.6), 1e-12);
  // Lit without shadows, a thicker medium is further from the reference; the map is closer than
  // none at either density.
  EXPECT_GT(t.rows[3].error, t.rows[0].error);
  for (int k : {0, 3}) EXPECT_LT(t.rows[k + 2].error, t.rows[k].error) << t.rows[k].label;
  // Where each leaves the target is read off the rows: none past it already at 0.4.
  const nlohmann::json& leaves = t.summary["leaves_target"];
  EXPECT_EQ(leaves["none"], 0.4);
  for (const auto& r : t.rows) {
    EXPECT_GT(r.time, 0.0) << r.label;
    if (r.error <= o.target) {
      EXPECT_TRUE(leaves[r.group].is_null() || leaves[r.group].get<double>() > r.extra[0]) << r.label;
    }
  }
}

TEST(ChartScattering, OctavesComeCloserToThePathTracedTruthThanOne) {
  ScatteringChartOptions o;
  o.octaves = {1, 4};
  o.width = 48;
  o.height = 48;
  o.samples = 128;
  o.frames = 1;
  const ChartTable t = chart_scattering(o);
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0].group, "single scattering");
  EXPECT_EQ(t.rows[1].label, "4 octaves");
  const double noise = t.summary["monte_carlo_error"].get<double>();
  EXPECT_LT(t.rows[1].error + 2.0 * noise, t.rows[0].error);
  for (const auto& r : t.rows) EXPECT_GT(r.time, 0.0) << r.label;
  EXPECT_TRUE(t.rows[1].pareto);
}

TEST(ChartParticleBudget, LooserTargetsKeepFewerParticlesAndCostError) {
  ParticleBudgetChartOptions o;
  o.files = {content_path("volumes/sample_cloud.vdb")};
  o.error_targets = {0.02, 0.12};
  o.width = o.height = 48;
  o.repeats = 1;
  const ChartTable t = chart_particle_budget(o);
  ASSERT_EQ(t.rows.size(), 2u);
  // Columns: error_target, particles, active_voxels, import_ms.
  EXPECT_GT(t.rows[0].extra[1], 2.0 * t.rows[1].extra[1]);
  EXPECT_LT(t.rows[0].extra[1], t.rows[0].extra[2]);  // fewer particles than voxels
  EXPECT_LT(t.rows[0].error, t.rows[1].error);
  EXPECT_LT(t.rows[0].error, 0.03);
}

}  // namespace
}  // namespace pyro
