// The scene file's "fires": every key read into the component, refusals with JSON
// pointers, and the command-line tools: `pyro bake-flipbook` (frames + manifest that read back as
// a flipbook; refusals with exit 2 and nothing written) and `pyro analyze flipbook-pattern`.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/core/user_error.h"
#include "systems/flipbook_fire/flipbook_folder.h"
#include "systems/runtime/scene/scene_loader.h"
#include "engine/math/color.h"
#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

std::string error_of_flipbook_scene(const std::string& text, const std::string& file = "fires.json") {
  try {
    parse_scene(text, file);
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

TEST(FlipbookScene, EveryKeyIsRead) {
  const fs::path dir = test::scratch_dir("keys");
  fs::create_directories(dir / "flames");
  const std::string file = (dir / "scene.json").string();
  const SceneDescription s = parse_scene(R"({"fires": [
    {"name": "f", "position": [1, 2, 3], "up": [0, 0, 1], "width": 0.4, "aspect": 2.5,
     "intensity": 0.7, "overlap_exponent": 1.5, "blend": "linear-alpha", "frames_per_second": 24,
     "flipbook": "flames",
     "preparation": {"crop": [0.1, 0.2, 0.9, 1], "base_line": 0.05, "soften": 0.1},
     "groups": [{"offset": [0.5, -0.2], "rows": 11, "columns": 7, "overlap": 0.25,
                 "row_spacing": 0.2, "column_depths": [0, 0.2], "start_frames": [3, -4, 7],
                 "row_start_step": -1, "increments": [1, -2, -2]}]},
    {}]})", file);
  ASSERT_EQ(s.fires.size(), 2u);
  const FlipbookFire& f = s.fires[0];
  EXPECT_EQ(f.name, "f");
  EXPECT_EQ(f.position, glm::vec3(1, 2, 3));
  EXPECT_EQ(f.up, glm::vec3(0, 0, 1));
  EXPECT_FLOAT_EQ(f.width, 0.4f);
  EXPECT_FLOAT_EQ(f.aspect, 2.5f);
  EXPECT_FLOAT_EQ(f.intensity, 0.7f);
  EXPECT_FLOAT_EQ(f.overlap_exponent, 1.5f);
  EXPECT_EQ(f.blend, FlipbookBlend::linear_alpha);
  EXPECT_FLOAT_EQ(f.frames_per_second, 24.0f);
  EXPECT_EQ(f.flipbook, (dir / "flames").string());
  EXPECT_EQ(f.preparation.crop, glm::vec4(0.1f, 0.2f, 0.9f, 1.0f));
  EXPECT_FLOAT_EQ(f.preparation.base_line, 0.05f);
  EXPECT_FLOAT_EQ(f.preparation.soften, 0.1f);
  ASSERT_EQ(f.groups.size(), 1u);
  const FlipbookGroup& g = f.groups[0];
  EXPECT_EQ(g.offset, glm::vec2(0.5f, -0.2f));
  EXPECT_EQ(g.rows, 11);
  EXPECT_EQ(g.columns, 7);
  EXPECT_FLOAT_EQ(g.overlap, 0.25f);
  EXPECT_FLOAT_EQ(g.row_spacing, 0.2f);
  EXPECT_EQ(g.column_depths, (std::vector<float>{0.0f, 0.2f}));
  EXPECT_EQ(g.start_frames, (std::vector<int>{3, -4, 7}));
  EXPECT_EQ(g.row_start_step, -1);
  EXPECT_EQ(g.increments, (std::vector<int>{1, -2, -2}));
  // An empty fire: the thesis' pairs, the baked flipbook, the (1 - dst, 1) blend.
  const FlipbookFire& d = s.fires[1];
  EXPECT_TRUE(d.flipbook.empty());
  EXPECT_EQ(d.blend, FlipbookBlend::one_minus_destination);
  ASSERT_EQ(d.groups.size(), 1u);
  EXPECT_EQ(d.groups[0].increments, (std::vector<int>{1, -2}));
  EXPECT_FLOAT_EQ(d.aspect, 1.5f);
}

TEST(FlipbookScene, ShippedScenesHaveTheThesisLayouts) {
  // campfire: one fire of overlapped pairs (m = 1, n = -2) and triplets (l = -2, m = 1, n = -2)
  // whose start frames differ; flipbook_grid: 11 rows of 7, 0.4 apart laterally, 0.2 in depth
  // (Rose 2007, figure 19).
  const SceneDescription campfire = load_scene(test::scene_path("campfire.json"));
  ASSERT_EQ(campfire.fires.size(), 1u);
  const std::vector<FlipbookGroup>& groups = campfire.fires[0].groups;
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].columns, 2);
  EXPECT_EQ(groups[0].increments, (std::vector<int>{1, -2}));
  EXPECT_EQ(groups[1].columns, 3);
  EXPECT_EQ(groups[1].increments, (std::vector<int>{-2, 1, -2}));
  // The groups overlap: their lateral extents share more than half a card.
  const float w = campfire.fires[0].width;
  auto extent = [&](const FlipbookGroup& g) {
    const float half = 0.5f * float(g.columns - 1) * w * (1.0f - g.overlap) + 0.5f * w;
    return std::pair(g.offset.x - half, g.offset.x + half);
  };
  const auto [a0, a1] = extent(groups[0]);
  const auto [b0, b1] = extent(groups[1]);
  EXPECT_GT(std::min(a1, b1) - std::max(a0, b0), 0.5f * w);
  const SceneDescription grid = load_scene(test::scene_path("flipbook_grid.json"));
  ASSERT_EQ(grid.fires.size(), 1u);
  const FlipbookFire& g = grid.fires[0];
  EXPECT_EQ(g.groups[0].rows, 11);
  EXPECT_EQ(g.groups[0].columns, 7);
  EXPECT_NEAR(g.width * (1.0f - g.groups[0].overlap), 0.4f, 1e-6f);
  EXPECT_NEAR(g.groups[0].row_spacing, 0.2f, 1e-6f);
  EXPECT_NEAR(g.groups[0].column_depths[1], 0.2f, 1e-6f);
}

TEST(FlipbookScene, RefusalsNameThePlace) {
  EXPECT_NE(error_of_flipbook_scene(R"({"fires": [{"blend": "one-minus-dest"}]})")
                .find("fires.json: at /fires/0/blend: unknown value \"one-minus-dest\""),
            std::string::npos);
  EXPECT_NE(error_of_flipbook_scene(R"({"fires": [{"widht": 1}]})").find("at /fires/0/widht: unknown key \"widht\"; did you mean \"width\"?"),
            std::string::npos);
  EXPECT_NE(error_of_flipbook_scene(R"({"fires": [{"up": [0, 0, 0]}]})").find("at /fires/0/up: expected a non-zero"),
            std::string::npos);
  EXPECT_NE(error_of_flipbook_scene(R"({"fires": [{"groups": [{"increments": [1, 2.5]}]}]})")
                .find("at /fires/0/groups/0/increments/1: expected an integer"),
            std::string::npos);
  EXPECT_NE(error_of_flipbook_scene(R"({"fires": [{"groups": []}]})").find("at /fires/0/groups: expected a non-empty array"),
            std::string::npos);
  EXPECT_NE(error_of_flipbook_scene(R"({"fires": [{"preparation": {"crop": [0.5, 0, 0.4, 1]}}]})")
                .find("at /fires/0/preparation/crop: expected [x0, y0, x1, y1]"),
            std::string::npos);
  EXPECT_NE(error_of_flipbook_scene(R"({"fires": [{"preparation": {"base_line": 0.6, "soften": 0.5}}]})")
                .find("at /fires/0/preparation/soften: expected base_line + soften at most 1"),
            std::string::npos);
  EXPECT_NE(error_of_flipbook_scene(R"({"fires": [{"groups": [{"rows": 100, "columns": 60}, {"rows": 100, "columns": 41}]}]})")
                .find("at /fires/0/groups: expected at most 10000 billboards in a fire"),
            std::string::npos);
  EXPECT_NE(error_of_flipbook_scene(R"({"fires": [{"groups": [{"overlap": 1}]}]})").find("at /fires/0/groups/0/overlap"),
            std::string::npos);
  EXPECT_NE(error_of_flipbook_scene(R"({"fires": [{"flipbook": "no/such/folder"}]})", "/tmp/x/fires.json")
                .find("at /fires/0/flipbook: expected a folder of PNG flame frames, found no folder at \"/tmp/x/no/such/folder\""),
            std::string::npos);
}

TEST(FlipbookScene, BakeWritesFramesThatReadBackAsAFlipbook) {
  const fs::path dir = test::scratch_dir("bake");
  const fs::path out = dir / "flames";
  const test::CommandResult r = test::run_pyro({"bake-flipbook", test::scene_path("flipbook_fire.json"), "--out",
                                                out.string(), "--frames", "3", "--width", "16",
                                                "--height", "24", "--loop-blend", "1", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = test::last_json_line(r.out);
  EXPECT_EQ(j["frames"], 3);
  EXPECT_EQ(j["files"].size(), 4u);
  const FlipbookFrames frames = read_flipbook_folder(out.string());
  ASSERT_EQ(frames.rgba.size(), 3u);
  EXPECT_EQ(frames.width, 16);
  EXPECT_EQ(frames.height, 24);
  // Fire on black: some light, and black (transparent) corners.
  int lit = 0;
  for (size_t i = 0; i < frames.rgba[2].size(); i += 4) lit += frames.rgba[2][i] > 64;
  EXPECT_GT(lit, 5);
  EXPECT_EQ(frames.rgba[2][3], 0);
  // Scenes with flipbook fires cannot be baked: exit 2, nothing written.
  std::ofstream(dir / "fires.json") << R"({"fires": [{}]})";
  const fs::path out2 = dir / "other";
  const test::CommandResult refused =
      test::run_pyro({"bake-flipbook", (dir / "fires.json").string(), "--out", out2.string()});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("/fires"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(out2));
}

TEST(FlipbookScene, BakeCrossFadesTheLoopsWrap) {
  // Raw: 6 simulated frames, no blending. Looped: 4 frames with a 2-frame cross-fade, which
  // simulates the same 6 steps: frame j < 2 = mix(raw[4 + j], raw[j]) in linear light with
  // weight (j + 1) / 3 on raw[j]; frames 2 and 3 are raw.
  const fs::path dir = test::scratch_dir("loop");
  const auto bake = [&](const std::string& name, const std::string& frames, const std::string& blend) {
    const test::CommandResult r =
        test::run_pyro({"bake-flipbook", test::scene_path("flipbook_fire.json"), "--out", (dir / name).string(),
                        "--frames", frames, "--width", "16", "--height", "24", "--loop-blend", blend});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_flipbook_folder((dir / name).string());
  };
  const FlipbookFrames raw = bake("raw", "6", "0");
  const FlipbookFrames looped = bake("looped", "4", "2");
  ASSERT_EQ(raw.rgba.size(), 6u);
  ASSERT_EQ(looped.rgba.size(), 4u);
  int differing = 0;
  for (int j = 0; j < 4; ++j)
    for (size_t i = 0; i < raw.rgba[0].size(); ++i) {
      if (i % 4 == 3) continue;  // alpha is derived from the colour
      const int got = looped.rgba[static_cast<size_t>(j)][i];
      int expected = raw.rgba[static_cast<size_t>(j)][i];
      if (j < 2) {
        const float w = (j + 1) / 3.0f;
        const float a = srgb_to_linear(raw.rgba[static_cast<size_t>(j)][i] / 255.0f);
        const float b = srgb_to_linear(raw.rgba[static_cast<size_t>(4 + j)][i] / 255.0f);
        expected = to_byte(linear_to_srgb(w * a + (1 - w) * b));
        differing += expected != raw.rgba[static_cast<size_t>(j)][i];
      }
      ASSERT_NEAR(got, expected, 1) << "frame " << j << " byte " << i;
    }
  EXPECT_GT(differing, 10) << "the cross-fade changes the first frames";
  const test::CommandResult refused = test::run_pyro({"bake-flipbook", test::scene_path("flipbook_fire.json"),
                                                      "--out", (dir / "x").string(), "--frames", "4",
                                                      "--loop-blend", "4"});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--loop-blend"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir / "x"));
}

TEST(FlipbookScene, PatternAnalysisReportsTheThesisPatterns) {
  const test::CommandResult r = test::run_pyro({"analyze", "flipbook-pattern", "--frames", "34", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = test::last_json_line(r.out);
  ASSERT_EQ(j["patterns"].size(), 5u);
  // All +1: 4 transfers a step among 6 billboards, one row away from the viewer.
  EXPECT_NEAR(j["patterns"][0]["march"].get<double>(), 4.0 / 6.0, 1e-12);
  EXPECT_NEAR(j["patterns"][1]["march"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(j["patterns"][2]["march"].get<double>(), 2.0 / 6.0, 1e-12);
  const test::CommandResult campfire =
      test::run_pyro({"analyze", "flipbook-pattern", "--scene", test::scene_path("campfire.json"), "--json"});
  ASSERT_EQ(campfire.exit_code, 0) << campfire.err;
  EXPECT_EQ(test::last_json_line(campfire.out)["patterns"].size(), 1u);  // one fire
}

}  // namespace
}  // namespace pyro
