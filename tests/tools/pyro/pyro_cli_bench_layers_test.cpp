// pyro bench layers end to end, small: the JSON it prints (per scale fps and RMSE
// against full resolution), the methods it ran with, and the comparison options. The RMSE at
// full resolution is 0 by definition; a reduced layer's is not.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(PyroCliBenchLayers, PrintsFpsAndErrorPerScale) {
  for (const char* billboards : {"sprites", "quads"}) {
    const auto r = test::run_pyro({"bench", "layers", test::scene_path("explosion.json"), "--width",
                                   "64", "--height", "64", "--frames", "6", "--scales", "1", "0.5",
                                   "--billboards", billboards, "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);  // one JSON object (progress goes to stderr)
    EXPECT_EQ(j["billboards"], billboards);
    EXPECT_EQ(j["compose"], "tiled");
    ASSERT_EQ(j["scales"].size(), 2u);
    EXPECT_EQ(j["scales"][0]["scale"].get<double>(), 1.0);
    EXPECT_EQ(j["scales"][0]["rmse_vs_full"].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(j["scales"][0]["speedup_vs_full"].get<double>(), 1.0);
    EXPECT_GT(j["scales"][1]["rmse_vs_full"].get<double>(), 0.0);
    EXPECT_LT(j["scales"][1]["rmse_vs_full"].get<double>(), 0.05);
    for (const auto& s : j["scales"]) EXPECT_GT(s["fps"].get<double>(), 0.0);
  }
  const auto bad = test::run_pyro({"bench", "layers", test::scene_path("explosion.json"),
                                   "--billboards", "hexagons"});
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("--billboards"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace pyro
