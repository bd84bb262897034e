// Reliability end to end: scene files that are garbage, truncated, mistyped or over budget are
// refused with exit status 2 naming the file and nothing written (not even a temporary folder);
// renders are deterministic and `--frames A:B` equals the same frames of a full run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/support/cli_render.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

using test::read_bytes;

std::string billion_particles() {
  std::string s = R"({"clouds": [)";
  for (int i = 0; i < 100; ++i) s += std::string(i ? "," : "") + R"({"count": 10000000})";
  return s + "]}";
}

std::string binary_garbage() {
  std::string s;
  uint32_t x = 12345;
  for (int i = 0; i < 4096; ++i) {
    x = x * 1664525u + 1013904223u;
    s.push_back(static_cast<char>(x >> 24));
  }
  s[0] = '\x89';  // not a '{'
  return s;
}

struct Refusal {
  const char* label;
  std::string text;
  const char* place;  // expected in the message
};

void PrintTo(const Refusal& c, std::ostream* os) { *os << c.label; }

class PyroCliRefusal : public ::testing::TestWithParam<Refusal> {};

TEST_P(PyroCliRefusal, ExitTwoNamingTheFileAndNothingWritten) {
  const Refusal& c = GetParam();
  const fs::path dir = test::scratch_dir(std::string("refusal_") + c.label);
  const fs::path scene = dir / (std::string(c.label) + ".json");
  std::ofstream(scene, std::ios::binary) << c.text;
  const fs::path out = dir / "frames";
  const auto r = test::run_pyro({"render", scene.string(), "--out", out.string(), "--frames", "3"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(scene.string()), std::string::npos) << "names the file: " << r.err;
  EXPECT_NE(r.err.find(c.place), std::string::npos) << "names the place: " << r.err;
  EXPECT_FALSE(fs::exists(out));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1u) << "only the scene file: no temporary folder left";
}

INSTANTIATE_TEST_SUITE_P(
    BadSceneFiles, PyroCliRefusal,
    ::testing::Values(
        Refusal{"binary_garbage", binary_garbage(), "line 1"},
        Refusal{"truncated", R"({"name": "t", "clouds": [{"count": 10, "radius": 0.)", "line 1"},
        Refusal{"truncated_mid_key", "{\"clouds\": [{\"cou", "line 1"},
        Refusal{"wrong_type_root", "[1, 2, 3]", "expected a JSON object"},
        Refusal{"wrong_type_clouds", R"({"clouds": {"count": 10}})", "/clouds"},
        Refusal{"wrong_type_width", R"({"output": {"width": "wide"}})", "/output/width"},
        Refusal{"billion_particles", billion_particles(), "/budget/particles"},
        Refusal{"budget_out_of_range", R"({"budget": {"particles": 1e12}})", "/budget/particles"},
        Refusal{"memory_budget", R"({"clouds": [{"count": 100}], "budget": {"memory_mib": 1}})",
                "/budget/memory_mib"},
        Refusal{"texture_budget", R"({"output": {"width": 300}, "budget": {"texture_size": 256}})",
                "/budget/texture_size"}),
    [](const auto& info) { return std::string(info.param.label); });

TEST(PyroCliFrames, BadRangesAreRefused) {
  const fs::path dir = test::scratch_dir("bad_ranges");
  for (const char* range : {"0", "5:3", "-1:4", "a:b", "3:", ":3", "2x", "1000000:1000001"}) {
    const auto r = test::run_pyro({"render", test::scene_path("mist.json"), "--out",
                                   (dir / "frames").string(), "--frames", range});
    EXPECT_EQ(r.exit_code, 2) << range << ": " << r.err;
    EXPECT_NE(r.err.find("--frames"), std::string::npos) << range << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "frames"));
}

// The explosion scene at 96 x 96 (the size does not change the simulation; it keeps the test
// short under the sanitizers).
test::CommandResult render_explosion(const fs::path& out, const std::string& frames) {
  return test::render("explosion.json", out, frames, 96);
}

TEST(PyroCliDeterminism, TwoRendersOfTheExplosionAreIdentical) {
  const fs::path dir = test::scratch_dir("explosion_twice");
  for (const char* name : {"a", "b"}) {
    const auto r = render_explosion(dir / name, "4");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  for (int f = 0; f < 4; ++f) {
    const std::string png = "frame_000" + std::to_string(f) + ".png";
    const std::string a = read_bytes(dir / "a" / png);
    ASSERT_FALSE(a.empty()) << png;
    EXPECT_EQ(a, read_bytes(dir / "b" / png)) << png;
  }
}

TEST(PyroCliDeterminism, FramesFiftyToFiftyNineAloneEqualAFullRun) {
  const fs::path dir = test::scratch_dir("explosion_resume");
  ASSERT_EQ(render_explosion(dir / "full", "60").exit_code, 0);
  const auto part = render_explosion(dir / "part", "50:59");
  ASSERT_EQ(part.exit_code, 0) << part.err;
  std::size_t written = 0;
  for (const auto& e : fs::directory_iterator(dir / "part"))
    written += e.path().filename() != ".pyro_manifest.json";
  EXPECT_EQ(written, 10u) << "frames 50..59 only, beside the folder's manifest";
  for (int f = 50; f <= 59; ++f) {
    const std::string png = "frame_00" + std::to_string(f) + ".png";
    const std::string whole = read_bytes(dir / "full" / png);
    ASSERT_FALSE(whole.empty()) << png;
    EXPECT_EQ(whole, read_bytes(dir / "part" / png)) << png;
  }
  // A sequence that moves: the frames differ from one another.
  EXPECT_NE(read_bytes(dir / "full" / "frame_0050.png"), read_bytes(dir / "full" / "frame_0059.png"));
}

}  // namespace
}  // namespace pyro
