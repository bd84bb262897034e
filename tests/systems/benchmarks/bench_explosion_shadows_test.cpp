// pyro bench explosion-shadows on the shipped explosion: the light phase's shadows on its dust and
// smoke (half-resolution layers) within the project's bar (0.03) of exact per-fragment shadows
// at full resolution, for the opacity shadow map and the shadow rays; with shadows off (the media
// shadowed by themselves alone) the frames are not.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine/core/content_path.h"
#include "systems/benchmarks/bench_explosion_shadows.h"

namespace pyro {
namespace {

TEST(BenchExplosionShadows, TheMethodsAreWithinTheBarAndShadowsOffIsNot) {
  ExplosionShadowsBenchOptions o;
  o.scene = content_path("scenes/explosion.json");
  o.width = o.height = 256;
  o.frames = 12;
  o.error_frames = 2;
  o.settings = {{ShadowMethod::shadow_map, 64, 32}, {ShadowMethod::rays, 64, 32}};
  const nlohmann::json j = bench_explosion_shadows(o);
  ASSERT_EQ(j["settings"].size(), 2u);
  for (const nlohmann::json& row : j["settings"]) {
    std::printf("%s: rmse %.4f, %.2fx shadows off\n", row["method"].get<std::string>().c_str(),
                row["rmse_vs_truth"].get<double>(), row["fps_over_off"].get<double>());
    EXPECT_LE(row["rmse_vs_truth"].get<double>(), 0.03);
    EXPECT_GT(row["fps"].get<double>(), 0.0);
  }
  std::printf("shadows off: rmse %.4f\n", j["off"]["rmse_vs_truth"].get<double>());
  EXPECT_GT(j["off"]["rmse_vs_truth"].get<double>(), 0.03);
}

TEST(BenchExplosionShadows, AGaussianSceneIsRefusedNamingTheKey) {
  ExplosionShadowsBenchOptions o;
  o.scene = content_path("scenes/clouds.json");
  try {
    bench_explosion_shadows(o);
    FAIL() << "clouds were measured as an explosion";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("/render"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pyro
