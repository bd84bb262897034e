// pyro bench scale end to end: a table or one JSON object with a row per count, and a scene
// without clouds refused with exit 2, naming the scene and its clouds.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(PyroCliBenchScale, PrintsARowPerCountAsTextAndAsJson) {
  const std::vector<std::string> args = {"bench", "scale", test::scene_path("fog.json"), "--counts", "1500",
                                         "3000", "--frames", "1", "--width", "48", "--height", "32"};
  const auto text = test::run_pyro(args);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("particles"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("\n        3000 "), std::string::npos) << text.out;
  std::vector<std::string> json_args = args;
  json_args.push_back("--json");
  const auto json = test::run_pyro(json_args);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json r = test::last_json_line(json.out);
  ASSERT_EQ(r["counts"].size(), 2u);
  EXPECT_EQ(r["counts"][0]["particles"], 1500);
  EXPECT_EQ(r["counts"][1]["particles"], 3000);
}

TEST(PyroCliBenchScale, ASceneWithoutCloudsIsRefused) {
  const auto r = test::run_pyro({"bench", "scale", test::scene_path("explosion.json"), "--counts", "1000"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("explosion.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("clouds"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace pyro
