// pyro analyze blackbody and pyro analyze phase end to end: the JSON they print against the
// published chromaticity and the normalisation bar; bad arguments exit 2.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(PyroCliMedia, BlackbodyAt2856KIsIlluminantA) {
  const auto r = test::run_pyro({"analyze", "blackbody", "--temperature", "2856", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["x"].get<double>(), 0.44757, 1e-3);
  EXPECT_NEAR(j["y"].get<double>(), 0.40745, 1e-3);
  ASSERT_EQ(j["rgb"].size(), 3u);
  ASSERT_EQ(j["XYZ"].size(), 3u);
  EXPECT_DOUBLE_EQ(j["rgb"][0].get<double>(), 1.0);  // red-dominant, normalised to max 1
}

TEST(PyroCliMedia, PhaseFunctionsIntegrateToOne) {
  for (const char* f : {"henyey-greenstein", "cornette-shanks"}) {
    const auto r = test::run_pyro({"analyze", "phase", "--function", f, "--g", "0.7", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j["integral"].get<double>(), 1.0, 1e-3) << f;
    EXPECT_NEAR(j["mean_cosine"].get<double>(), j["mean_cosine_closed_form"].get<double>(), 1e-6) << f;
  }
  const auto bad = test::run_pyro({"analyze", "phase", "--function", "rayleigh", "--g", "0"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--function"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace pyro
