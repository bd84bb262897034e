// `pyro bake-flipbook` replaces its folder as a whole (engine/io/folder_replacement.h): killed
// before any of its renames (PYRO_TEST_KILL_BEFORE_RENAME, engine/io/rename_fault.h), it leaves
// the old bake or the new one, byte for byte, never a mix; the next bake removes what the killed
// one left; and a bake of fewer frames leaves exactly its own frames.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "tests/support/cli_render.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;
using test::contents;

test::CommandResult bake(const fs::path& out, int frames, const std::string& launcher = "") {
  return test::run_pyro_with(launcher, {"bake-flipbook", test::scene_path("flipbook_fire.json"), "--out",
                                        out.string(), "--frames", std::to_string(frames), "--loop-blend", "1",
                                        "--width", "16", "--height", "24"});
}

// What the folder's parent holds besides `keep`: leftovers of killed bakes.
std::vector<std::string> beside(const fs::path& out) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(out.parent_path()))
    if (e.path().filename() != out.filename()) names.push_back(e.path().filename().string());
  return names;
}

TEST(PyroCliBakeAtomic, AKillBetweenAnyTwoRenamesLeavesTheOldBakeOrTheNew) {
  const fs::path dir = test::scratch_dir("bake_atomic");
  const fs::path old_bake = dir / "reference_old" / "fire", new_bake = dir / "reference_new" / "fire";
  ASSERT_EQ(bake(old_bake, 4).exit_code, 0);
  ASSERT_EQ(bake(new_bake, 3).exit_code, 0);
  const auto old_files = contents(old_bake), new_files = contents(new_bake);
  ASSERT_NE(old_files, new_files);
  int killed = 0;
  // A bake of 3 frames renames 3 frames, flipbook.json and its manifest into its folder, then the
  // folder.
  for (int n = 1; n <= 7; ++n) {
    const fs::path out = dir / ("trial_" + std::to_string(n)) / "fire";
    fs::create_directories(out.parent_path());
    fs::copy(old_bake, out);
    const auto r = bake(out, 3, "env PYRO_TEST_KILL_BEFORE_RENAME=" + std::to_string(n));
    killed += r.exit_code != 0;
    const auto now = contents(out);
    EXPECT_TRUE(now == old_files || now == new_files) << "kill before rename " << n << ": a mix of bakes";
    EXPECT_EQ(now == new_files, r.exit_code == 0) << "kill before rename " << n;
    // The next bake removes what the killed one left beside the folder.
    ASSERT_EQ(bake(out, 3).exit_code, 0);
    EXPECT_EQ(contents(out), new_files);
    EXPECT_TRUE(beside(out).empty()) << "kill before rename " << n << ": " << beside(out).front();
  }
  EXPECT_EQ(killed, 6) << "every rename up to the folder's was a kill point";
}

TEST(PyroCliBakeAtomic, ABakeOfFewerFramesLeavesExactlyItsOwn) {
  const fs::path dir = test::scratch_dir("bake_fewer");
  const fs::path out = dir / "fire";
  ASSERT_EQ(bake(out, 4).exit_code, 0);
  ASSERT_EQ(bake(out, 2).exit_code, 0);
  const auto files = contents(out);
  EXPECT_EQ(files.size(), 4u);
  EXPECT_EQ(files.count("frame_0000.png") + files.count("frame_0001.png") + files.count("flipbook.json") +
                files.count(".pyro_manifest.json"),
            4u);
  // A scene using the folder loads it.
  const fs::path scene = dir / "scene.json";
  std::ofstream(scene) << R"({"fires": [{"flipbook": "fire"}], "output": {"width": 32, "height": 32}})";
  const auto r = test::run_pyro({"render", scene.string(), "--out", (dir / "frames").string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(PyroCliBakeAtomic, ABakeMayNotReplaceTheFolderHoldingItsScene) {
  const fs::path dir = test::scratch_dir("bake_own_scene");
  fs::copy_file(test::scene_path("flipbook_fire.json"), dir / "fire.json");
  const auto r = test::run_pyro({"bake-flipbook", (dir / "fire.json").string(), "--out", dir.string(),
                                 "--frames", "2", "--loop-blend", "0"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(fs::exists(dir / "fire.json"));
}

}  // namespace
}  // namespace pyro
