// `pyro chart NAME --out DIR`, end to end: the CSV is written (and the PNG when Debian's
// matplotlib is there), and mistakes exit 2 writing nothing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"

namespace pyro::test {
namespace {

bool have_matplotlib() {
  return std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

TEST(PyroChartCli, IntegratorsChartWritesItsCsvAndPng) {
  const auto dir = scratch_dir("chart_integrators");
  const bool png = have_matplotlib();
  std::vector<std::string> args = {"chart", "integrators", "--out", (dir / "out").string(), "--json"};
  if (!png) args.push_back("--csv-only");
  const CommandResult r = run_pyro(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = last_json_line(r.out);
  EXPECT_EQ(j["chart"], "integrators");
  std::ifstream csv(dir / "out" / "integrators.csv");
  std::stringstream text;
  text << csv.rdbuf();
  EXPECT_NE(text.str().find("# ground truth: the exact solution"), std::string::npos);
  EXPECT_NE(text.str().find("label,group,time,error,dt,steps,k_dt,blew_up,pareto,usable,front"),
            std::string::npos);
  if (png)
    EXPECT_GT(std::filesystem::file_size(dir / "out" / "integrators.png"), 10000u);
  else
    GTEST_SKIP() << "/usr/bin/python3 has no matplotlib: the PNG is not checked";
}

TEST(PyroChartCli, UnknownChartExitsTwoAndWritesNothing) {
  const auto dir = scratch_dir("chart_unknown");
  const CommandResult r = run_pyro({"chart", "speed", "--out", (dir / "out").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("speed"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(PyroChartCli, AnOptionTheChartDoesNotUseIsRefused) {
  const auto dir = scratch_dir("chart_unused_option");
  const CommandResult r = run_pyro({"chart", "footprint", "--frames", "3", "--out", (dir / "out").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--frames"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  const CommandResult density = run_pyro({"chart", "footprint", "--density", "--out", (dir / "out").string()});
  EXPECT_EQ(density.exit_code, 2);
  EXPECT_NE(density.err.find("--density"), std::string::npos) << density.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

}  // namespace
}  // namespace pyro::test
