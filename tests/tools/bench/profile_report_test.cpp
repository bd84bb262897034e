// A profiling run's report, against what the run itself knows: one row per scheduled system
// with one sample per counted frame (the warm-up left out), GPU passes for the render systems,
// frame times that bound the systems', and the particles the world holds.
#include <gtest/gtest.h>

#include <string>

#include "components/particle_set.h"
#include "tools/bench/profile_report.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/particle_counts.h"
#include "tests/support/small_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(ProfileReport, OneSamplePerCountedFrameForEverySystem) {
  RuntimeOptions o = test::small_runtime();
  o.profile = true;
  SceneRuntime runtime(load_scene(test::scene_path("explosion.json")), o);
  const int warmup = 2, counted = 5;
  for (int f = 0; f < warmup + counted; ++f) runtime.step();
  const nlohmann::json r = profile_report(runtime, warmup);

  ASSERT_EQ(r["systems"].size(), runtime.schedule().stats().size());
  double system_mean_sum = 0.0;
  for (const auto& row : r["systems"]) {
    EXPECT_EQ(row["samples"], counted) << row["name"];
    EXPECT_LE(row["min_ms"].get<double>(), row["median_ms"].get<double>());
    EXPECT_LE(row["median_ms"].get<double>(), row["max_ms"].get<double>());
    system_mean_sum += row["mean_ms"].get<double>();
  }
  // A frame span covers its systems' spans (they may overlap when run in parallel).
  EXPECT_GE(r["frame_mean_ms"].get<double>() * 1.0001, r["systems"][0]["mean_ms"].get<double>());
  EXPECT_GT(system_mean_sum, 0.0);
  bool billboard_pass = false;
  for (const auto& row : r["gpu_passes"]) billboard_pass |= row["name"] == "billboard_render";
  EXPECT_TRUE(billboard_pass);
  // Counted here from the pools themselves, and a slot's size from its fields (16 floats, the
  // medium byte, the id), independently of the report's own census.
  uint64_t live = 0, capacity = 0;
  runtime.world().each<ParticleSet>([&](ecs::Entity, ParticleSet& set) {
    live += set.pool.size();
    capacity += set.pool.capacity();
  });
  EXPECT_EQ(r["particles"]["live"], live);
  EXPECT_EQ(r["memory"]["pool_bytes"], capacity * (16 * 4 + 1 + 4));
}

}  // namespace
}  // namespace pyro
