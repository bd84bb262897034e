// `pyro import-vdb` on an animated sequence and `pyro render` of a scene that plays it: a pattern
// imported into one .pyroseq folder, a range of frames rendered byte for byte as in a full run,
// frames that differ; a gap or a damaged member refused by name with nothing written and an
// older output left as it was; the OpenUSD smoke pair's empty first frame drawing nothing.
#include <gtest/gtest.h>

#include <fstream>

#include "engine/volume/puff_sequence.h"
#include "tests/support/cli_render.h"
#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

test::CommandResult import_pyro_cli_vdb_sequence(const std::string& input, const fs::path& out, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"import-vdb", input, "--out", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return test::run_pyro(args);
}

fs::path write_scene_pyro_cli_vdb_sequence(const fs::path& dir, const std::string& volume) {
  const fs::path scene = dir / "scene.json";
  std::ofstream(scene) << R"({"output": {"fps": 30}, "background": [0.2, 0.3, 0.4],
    "camera": {"position": [0, 0.3, 2.2], "target": [0, 0, 0], "fov_y_deg": 45},
    "volumes": [)" << volume << "]}";
  return scene;
}

test::CommandResult render_pyro_cli_vdb_sequence(const fs::path& scene, const fs::path& out, const std::string& frames) {
  return test::run_pyro({"render", scene.string(), "--out", out.string(), "--frames", frames, "--width", "48",
                         "--height", "48"});
}

std::string frame_png(const fs::path& out, int f) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", f);
  return test::read_bytes(out / name);
}

class PyroCliVdbSequence : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::scratch_dir("vdb_sequence");
    fs::create_directories(dir_ / "vdb");
    PuffSequenceOptions puff;
    puff.frames = 6;
    puff.side = 16;
    paths_ = write_puff_sequence((dir_ / "vdb").string(), puff);
    pattern_ = (dir_ / "vdb" / "puff_%04d.vdb").string();
  }
  fs::path dir_;
  std::vector<std::string> paths_;
  std::string pattern_;
};

TEST_F(PyroCliVdbSequence, ImportsAPatternAndRendersARangeAsAFullRunDoes) {
  const fs::path out = dir_ / "puff.pyroseq";
  const auto r = import_pyro_cli_vdb_sequence(pattern_, out, {"--fps", "12", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = test::last_json_line(r.out);
  EXPECT_EQ(j["frames"], 6);
  EXPECT_EQ(j["first_frame"], 1);
  EXPECT_EQ(j["empty_frames"], 0);
  EXPECT_GT(j["frames_per_second"].get<double>(), 0.0);
  EXPECT_TRUE(fs::is_regular_file(out / "sequence.json"));
  EXPECT_TRUE(fs::is_regular_file(out / "frame_000006.pyrop"));
  // 12 source fps at 30 scene fps: frames 0..7 are positions 0, 0.4, ..., 2.8.
  const fs::path scene = write_scene_pyro_cli_vdb_sequence(dir_, R"({"file": "puff.pyroseq"})");
  const fs::path full = dir_ / "full", range = dir_ / "range";
  ASSERT_EQ(render_pyro_cli_vdb_sequence(scene, full, "0:7").exit_code, 0);
  const auto ranged = render_pyro_cli_vdb_sequence(scene, range, "5:7");
  ASSERT_EQ(ranged.exit_code, 0) << ranged.err;
  for (int f = 5; f <= 7; ++f) {
    ASSERT_FALSE(frame_png(range, f).empty()) << f;
    EXPECT_EQ(frame_png(range, f), frame_png(full, f)) << "frame " << f;
  }
  EXPECT_NE(frame_png(full, 0), frame_png(full, 7)) << "the puff moves";
  EXPECT_NE(frame_png(full, 5), frame_png(full, 6)) << "in-between frames differ";
}

TEST_F(PyroCliVdbSequence, AGapOrADamagedMemberIsRefusedByNameAndNothingIsWritten) {
  const fs::path out = dir_ / "puff.pyroseq";
  ASSERT_EQ(import_pyro_cli_vdb_sequence(pattern_, out).exit_code, 0);
  const auto before = test::contents(out);
  fs::resize_file(paths_[3], fs::file_size(paths_[3]) / 2);
  auto r = import_pyro_cli_vdb_sequence(pattern_, out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(paths_[3]), std::string::npos) << r.err;
  fs::remove(paths_[2]);
  r = import_pyro_cli_vdb_sequence((dir_ / "vdb" / "puff_*.vdb").string(), dir_ / "new.pyroseq");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find((dir_ / "vdb" / "puff_0003.vdb").string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("consecutive"), std::string::npos) << r.err;
  EXPECT_EQ(test::contents(out), before) << "the older output was touched";
  EXPECT_FALSE(fs::exists(dir_ / "new.pyroseq"));
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos) << e.path();
  r = import_pyro_cli_vdb_sequence((dir_ / "nothing_%04d.vdb").string(), dir_ / "x.pyroseq");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("found none matching the pattern"), std::string::npos) << r.err;
  r = import_pyro_cli_vdb_sequence(pattern_, dir_ / "x.pyrop");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(".pyroseq"), std::string::npos) << r.err;
  r = import_pyro_cli_vdb_sequence(pattern_, dir_ / "x.pyroseq", {"--temperature-grid", "heat"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--temperature-grid"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.pyroseq"));
}

TEST(PyroCliVdbSequenceShared, TheEmptyFirstFrameOfTheOpenUsdSmokeDrawsNothing) {
  const fs::path shared = fs::path(PYRO_SHARED_DATA_DIR) / "vdb";
  if (!fs::is_regular_file(shared / "openusd_smoke_000002.vdb"))
    GTEST_SKIP() << "no third-party VDB files at " PYRO_SHARED_DATA_DIR "/vdb (optional data)";
  const fs::path dir = test::scratch_dir("openusd_pair");
  fs::create_directories(dir / "smoke");
  fs::create_symlink(shared / "openusd_smoke_000001_blender_empty_grids.vdb", dir / "smoke" / "smoke_000001.vdb");
  fs::create_symlink(shared / "openusd_smoke_000002.vdb", dir / "smoke" / "smoke_000002.vdb");
  const auto r = import_pyro_cli_vdb_sequence((dir / "smoke").string(), dir / "smoke.pyroseq", {"--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::last_json_line(r.out)["empty_frames"], 1);
  // 15 source fps at 30: frame 0 is source frame 1 alone (empty), frame 2 source frame 2 alone.
  const fs::path scene = write_scene_pyro_cli_vdb_sequence(dir, R"({"file": "smoke.pyroseq", "size": 1.5, "speed": 0.625})");
  const fs::path empty_scene = write_scene_pyro_cli_vdb_sequence(dir / "smoke", "");
  ASSERT_EQ(render_pyro_cli_vdb_sequence(scene, dir / "out", "0:2").exit_code, 0);
  ASSERT_EQ(render_pyro_cli_vdb_sequence(empty_scene, dir / "none", "0:0").exit_code, 0);
  EXPECT_EQ(frame_png(dir / "out", 0), frame_png(dir / "none", 0)) << "the empty frame drew something";
  EXPECT_NE(frame_png(dir / "out", 2), frame_png(dir / "none", 0)) << "frame 2 drew nothing";
}

}  // namespace
}  // namespace pyro
