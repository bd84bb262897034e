// The pyro command line end to end: a render with its JSON summary, the footprint analysis,
// and refusals of bad scene files and arguments (exit status 2, the file named, nothing written).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "engine/io/png_file.h"
#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

TEST(PyroCli, RenderWritesFramesAndSummary) {
  const fs::path out = test::scratch_dir("render") / "frames";
  const auto r = test::run_pyro({"render", test::scene_path("mist.json"), "--out", out.string(),
                                 "--width", "96", "--height", "64", "--frames", "3", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = test::last_json_line(r.out);
  EXPECT_EQ(j["frames"], 3);
  EXPECT_EQ(j["width"], 96);
  EXPECT_EQ(j["height"], 64);
  EXPECT_EQ(j["particles"], 1000);
  ASSERT_EQ(j["files"].size(), 3u);
  for (int f = 0; f < 3; ++f) {
    const fs::path png = out / ("frame_000" + std::to_string(f) + ".png");
    ASSERT_TRUE(fs::exists(png)) << png;
    const PngImage img = read_png(png.string());
    EXPECT_EQ(img.width, 96);
    EXPECT_EQ(img.height, 64);
  }
  EXPECT_GT(j["seconds"].get<double>(), 0.0);
  // No temporary files left behind: the frames and the folder's manifest only.
  for (const auto& e : fs::directory_iterator(out))
    if (e.path().filename() != ".pyro_manifest.json") {
      EXPECT_EQ(e.path().extension(), ".png") << e.path();
    }
}

TEST(PyroCli, AnalyzeFootprintMeetsTheBar) {
  const auto r = test::run_pyro({"analyze", "footprint", "--size", "64", "--intervals", "100", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = test::last_json_line(r.out);
  EXPECT_LE(j["max_abs_error"].get<double>(), 2e-3);
  EXPECT_GT(j["max_abs_error"].get<double>(), 0.0);
}

struct BadScene {
  const char* label;
  const char* text;     // nullptr: the file does not exist
  const char* place;    // expected in the message (JSON pointer or line/column)
};

void PrintTo(const BadScene& c, std::ostream* os) { *os << c.label; }

class PyroCliBadScene : public ::testing::TestWithParam<BadScene> {};

TEST_P(PyroCliBadScene, RefusedWithExitTwoAndNothingWritten) {
  const BadScene& c = GetParam();
  const fs::path dir = test::scratch_dir(c.label);
  const fs::path scene = dir / (std::string(c.label) + ".json");
  if (c.text) std::ofstream(scene) << c.text;
  const fs::path out = dir / "frames";
  const auto r = test::run_pyro({"render", scene.string(), "--out", out.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(scene.string()), std::string::npos) << "names the file: " << r.err;
  EXPECT_NE(r.err.find(c.place), std::string::npos) << "names the place: " << r.err;
  EXPECT_FALSE(fs::exists(out)) << "nothing may be written";
}

INSTANTIATE_TEST_SUITE_P(
    Mistakes, PyroCliBadScene,
    ::testing::Values(
        BadScene{"syntax", "{\n  \"seed\": 3,\n  \"clouds\": [ {\"count\": 10,} ]\n}\n", "line 3"},
        BadScene{"wrong_type", R"({"clouds": [{"count": "many"}]})", "/clouds/0/count"},
        BadScene{"out_of_range", R"({"clouds": [{"count": 10, "density": 1.5}]})", "/clouds/0/density"},
        BadScene{"unknown_key", R"({"clouds": [{"count": 10, "raduis": 0.4}]})", "raduis"},
        BadScene{"missing_file", nullptr, "cannot open"}),
    [](const auto& info) { return std::string(info.param.label); });

TEST(PyroCli, BadArgumentsExitTwo) {
  EXPECT_EQ(test::run_pyro({"render"}).exit_code, 2);
  EXPECT_EQ(test::run_pyro({"analyze", "footprint", "--size", "1"}).exit_code, 2);
  const auto r = test::run_pyro({"analyze", "footprint", "--rule", "simpson", "--intervals", "7"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--intervals"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace pyro
