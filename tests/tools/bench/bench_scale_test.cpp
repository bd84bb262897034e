// pyro bench scale: the clouds scaled to each count keep N r^3 (their mean optical depth), each
// count's report carries the figures and ratios it names, a scene without clouds is refused, and
// the log-log slope is the exponent of a power law.
#include "tools/bench/bench_scale.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/user_error.h"
#include "systems/runtime/scene/scene_loader.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(BenchScale, CloudsKeepCountTimesRadiusCubed) {
  SceneDescription scene;
  scene.clouds.resize(2);
  scene.clouds[0].count = 3000;
  scene.clouds[0].radius = 0.5f;
  scene.clouds[1].count = 1000;
  scene.clouds[1].radius = 0.2f;
  const SceneDescription scaled = scale_clouds(scene, 400000);
  ASSERT_EQ(scaled.clouds.size(), 2u);
  EXPECT_EQ(scaled.clouds[0].count, 300000u);  // each keeps its share of the total
  EXPECT_EQ(scaled.clouds[1].count, 100000u);
  for (size_t c = 0; c < 2; ++c) {
    const double before = scene.clouds[c].count * std::pow(double(scene.clouds[c].radius), 3);
    const double after = scaled.clouds[c].count * std::pow(double(scaled.clouds[c].radius), 3);
    EXPECT_NEAR(after / before, 1.0, 1e-5) << c;
  }
  EXPECT_GE(scaled.budget.particles, 400000u);
}

TEST(BenchScale, ReportsEachCountWithItsBaselines) {
  ScaleBenchOptions o;
  o.scene = test::scene_path("clouds.json");
  o.counts = {3000, 12000};
  o.frames = 2;
  o.width = 64;
  o.height = 48;
  // The CPU's order, whose std::sort baseline is measured: under "auto" a loaded machine can
  // measure the GPU's order faster, and a GPU order has no such baseline.
  o.sort_device = SortDevice::cpu;
  const nlohmann::json r = bench_scale(o);
  ASSERT_EQ(r["counts"].size(), 2u);
  EXPECT_EQ(r["width"], 64);
  for (size_t i = 0; i < 2; ++i) {
    const nlohmann::json& c = r["counts"][i];
    EXPECT_EQ(c["particles"], o.counts[i]);
    const double frame = c["ms_per_frame"], cpu = c["cpu_ms_per_frame"];
    EXPECT_GT(cpu, 0.0);
    EXPECT_LT(cpu, frame);
    EXPECT_GT(c["std_sort_ms"].get<double>(), 0.0);
    EXPECT_GT(c["memcpy_instances_ms"].get<double>(), 0.0);
    // The splats upload two vec4s per particle and a 32-bit index per drawn one (the draw order
    // leaves out what the view cannot show).
    const double drawn = c["drawn_particles"];
    EXPECT_GT(drawn, 0.9 * double(o.counts[i]));
    EXPECT_LE(drawn, double(o.counts[i]));
    EXPECT_NEAR(c["bytes_per_particle"]["instances"].get<double>(),
                32.0 + 4.0 * drawn / double(o.counts[i]), 1e-9);
    EXPECT_TRUE(c["system_ms"].contains("sorting"));
    EXPECT_TRUE(c["system_ms"].contains("billboard_render"));
  }
  EXPECT_TRUE(r["cpu_slope"].is_null());  // no count from 1e5 to 2e6
  // Without culling every particle is drawn: an index for each.
  o.cull = false;
  o.counts = {o.counts[0]};
  const nlohmann::json all = bench_scale(o);
  EXPECT_EQ(all["cull"], false);
  EXPECT_EQ(all["counts"][0]["drawn_particles"].get<double>(), double(o.counts[0]));
  EXPECT_DOUBLE_EQ(all["counts"][0]["bytes_per_particle"]["instances"].get<double>(), 36.0);
}

TEST(BenchScale, ASceneWithoutCloudsIsRefused) {
  ScaleBenchOptions o;
  o.scene = test::scene_path("explosion.json");
  o.counts = {1000};
  o.frames = 1;
  EXPECT_THROW(bench_scale(o), UserError);
}

TEST(BenchScale, SlopeOfAPowerLawIsItsExponent) {
  std::vector<double> x, y;
  for (double n : {1e5, 3e5, 1e6, 2e6}) {
    x.push_back(n);
    y.push_back(0.002 * std::pow(n, 1.25));
  }
  EXPECT_NEAR(log_log_slope(x, y), 1.25, 1e-9);
  EXPECT_TRUE(std::isnan(log_log_slope({1e5}, {3.0})));
  EXPECT_TRUE(std::isnan(log_log_slope({1e5, 1e5}, {3.0, 4.0})));
}

}  // namespace
}  // namespace pyro
