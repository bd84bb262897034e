// pyro bench explosion-shadows on the shipped explosion: the light phase's shadows and fire light
// on its dust and smoke (half-resolution layers) within the project's bar (0.03) of exact
// per-fragment shadows and fire light at full resolution, for the opacity shadow map and the
// shadow rays; with shadows off (the media shadowed by themselves alone) the frames are more than
// twice as far from it.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/content_path.h"
#include "tools/bench/bench_explosion_shadows.h"

namespace pyro {
namespace {

// A small run of the bench on a shipped scene: 256x256, 12 frames, the error on 2 of them.
ExplosionShadowsBenchOptions small_run(const char* scene, std::vector<ShadowSettings> settings) {
  ExplosionShadowsBenchOptions o;
  o.scene = content_path(std::string("scenes/") + scene);
  o.width = o.height = 256;
  o.frames = 12;
  o.error_frames = 2;
  o.settings = std::move(settings);
  return o;
}

TEST(BenchExplosionShadows, TheMethodsAreWithinTheBarAndShadowsOffIsFarther) {
  const ExplosionShadowsBenchOptions o =
      small_run("explosion.json", {{ShadowMethod::shadow_map, 64, 32}, {ShadowMethod::rays, 64, 32}});
  const nlohmann::json j = bench_explosion_shadows(o);
  ASSERT_EQ(j["settings"].size(), 2u);
  const double off = j["off"]["rmse_vs_truth"].get<double>();
  std::printf("shadows off: rmse %.4f\n", off);
  for (const nlohmann::json& row : j["settings"]) {
    std::printf("%s: rmse %.4f, %.2fx shadows off\n", row["method"].get<std::string>().c_str(),
                row["rmse_vs_truth"].get<double>(), row["fps_over_off"].get<double>());
    EXPECT_LE(row["rmse_vs_truth"].get<double>(), 0.03);
    EXPECT_GT(off, 2.0 * row["rmse_vs_truth"].get<double>());
    EXPECT_GT(row["fps"].get<double>(), 0.0);
  }
}

// At dusk the fire's light matters: without fire lights the frames are farther from the truth
// (which scatters every fire particle's light) than with them. Leaving the fire light out of
// the lit dust and smoke shader fails it (0.0060 against 0.0068).
TEST(BenchExplosionShadows, AtDuskTheFireLightsBringTheFramesToTheTruth) {
  const ExplosionShadowsBenchOptions o =
      small_run("explosion_dusk.json", {{ShadowMethod::shadow_map, 32, 16, 0}, {ShadowMethod::shadow_map, 32, 16, 1},
                                        {ShadowMethod::shadow_map, 32, 16, 4}});
  const nlohmann::json j = bench_explosion_shadows(o);
  ASSERT_EQ(j["settings"].size(), 3u);
  const double none = j["settings"][0]["rmse_vs_truth"], one = j["settings"][1]["rmse_vs_truth"],
               four = j["settings"][2]["rmse_vs_truth"];
  std::printf("dusk: no fire lights %.5f, one %.5f, four %.5f\n", none, one, four);
  EXPECT_LT(four, 0.8 * none);  // the layers' own error (half resolution) is most of what is left
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
