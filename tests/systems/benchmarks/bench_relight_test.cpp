// pyro bench relight on the project's sample cloud: imported once, relit from three sun
// directions by the light phase, each frame within the project's bar (0.03) of the CPU volume
// reference lit from that direction; lit without shadows, the frames are not.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine/core/content_path.h"
#include "systems/benchmarks/bench_relight.h"

namespace pyro {
namespace {

nlohmann::json relight(ShadowMethod method) {
  RelightBenchOptions o;
  o.file = content_path("volumes/sample_cloud.vdb");
  o.directions = 3;
  o.width = 96;
  o.height = 96;
  o.frames = 2;
  o.shadows.method = method;
  return bench_relight(o);
}

TEST(BenchRelight, EveryDirectionIsWithinTheBarOfItsReference) {
  const nlohmann::json j = relight(ShadowMethod::shadow_map);
  ASSERT_EQ(j["directions"].size(), 3u);
  for (const nlohmann::json& d : j["directions"]) {
    std::printf("direction %s: rmse %.4f\n", d["direction"].dump().c_str(), d["rmse_vs_reference"].get<double>());
    EXPECT_LE(d["rmse_vs_reference"].get<double>(), 0.03);
  }
  EXPECT_GT(j["particles"].get<int>(), 100);
  EXPECT_GT(j["fps"].get<double>(), 0.0);
  EXPECT_GT(j["unlit_fps"].get<double>(), 0.0);
}

TEST(BenchRelight, WithoutShadowsTheFramesAreNot) {
  const nlohmann::json j = relight(ShadowMethod::none);
  std::printf("lit without shadows: max rmse %.4f\n", j["max_rmse_vs_reference"].get<double>());
  EXPECT_GT(j["max_rmse_vs_reference"].get<double>(), 0.03);
}

}  // namespace
}  // namespace pyro
