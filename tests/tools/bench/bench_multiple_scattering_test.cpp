// pyro bench multiple-scattering on the project's sample cloud: from three sun directions the
// octave approximation, ray marched and as the engine's lit splats draw it, comes closer to the
// path-traced truth than single scattering, by more than the truth's Monte Carlo error; with one
// octave it is single scattering and comes no closer.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "tools/bench/bench_multiple_scattering.h"

namespace pyro {
namespace {

MultipleScatteringBenchOptions small_run_bench_multiple_scattering(int octaves) {
  MultipleScatteringBenchOptions o;
  o.file = content_path("volumes/sample_cloud.vdb");
  o.width = 64;
  o.height = 64;
  o.samples = 128;
  o.sun.octaves.octaves = octaves;
  return o;
}

TEST(BenchMultipleScattering, OctavesComeCloserToThePathTracedTruth) {
  const nlohmann::json j = bench_multiple_scattering(small_run_bench_multiple_scattering(4));
  ASSERT_EQ(j["directions"].size(), 3u);
  for (const nlohmann::json& d : j["directions"]) {
    const double mc = d["monte_carlo_error"].get<double>(), ss = d["single_scattering_rmse"].get<double>(),
                 ms = d["octaves_rmse"].get<double>(), engine_ss = d["engine_single_rmse"].get<double>(),
                 engine_ms = d["engine_octaves_rmse"].get<double>();
    std::printf("direction %s: single %.4f, octaves %.4f, engine %.4f / %.4f, Monte Carlo %.4f\n",
                d["direction"].dump().c_str(), ss, ms, engine_ss, engine_ms, mc);
    EXPECT_EQ(d["truncated_paths"].get<int>(), 0);
    EXPECT_LT(ms + 2.0 * mc, ss);
    EXPECT_LT(engine_ms + 2.0 * mc, engine_ss);
  }
  EXPECT_TRUE(j["octaves_closer_everywhere"].get<bool>());
  EXPECT_TRUE(j["engine_octaves_closer_everywhere"].get<bool>());
}

TEST(BenchMultipleScattering, OneOctaveIsSingleScattering) {
  MultipleScatteringBenchOptions o = small_run_bench_multiple_scattering(1);
  o.directions = 1;
  o.samples = 8;
  const nlohmann::json j = bench_multiple_scattering(o);
  EXPECT_DOUBLE_EQ(j["max_octaves_rmse"].get<double>(), j["max_single_scattering_rmse"].get<double>());
  EXPECT_FALSE(j["octaves_closer_everywhere"].get<bool>());
}

TEST(BenchMultipleScattering, OctavesOutOfRangeAreRefused) {
  MultipleScatteringBenchOptions o = small_run_bench_multiple_scattering(4);
  o.sun.octaves.attenuation = 0.0;
  EXPECT_THROW(bench_multiple_scattering(o), UserError);
}

}  // namespace
}  // namespace pyro
