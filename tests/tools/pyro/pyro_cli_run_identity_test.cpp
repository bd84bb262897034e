// A render's output folder is keyed on the run's content (systems/runtime/scene_runtime/run_identity.h):
// an edited scene or asset is drawn again on --resume and counted, an edited scene rendered again
// into its own folder replaces its earlier render, a folder holding another run is refused naming
// what differs, --overwrite removes only that run's files, a reformatted scene is the same run,
// scenes read from pipes get the identity of what they say, and a frame whose bytes differ from
// the SHA-256 the manifest records is never kept.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <vector>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/io/particle_file.h"
#include "tests/support/cli_render.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;
using test::contents;
using test::read_bytes;

void write_text_pyro_cli_run_identity(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// The scene file `name` of content/scenes with `edit` applied to its JSON, written to `to`.
void write_edited_scene(const std::string& name, const fs::path& to,
                        const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json j = nlohmann::json::parse(read_bytes(test::scene_path(name)));
  edit(j);
  write_text_pyro_cli_run_identity(to, j.dump(2));
}

test::CommandResult render_file(const fs::path& scene, const fs::path& out, const std::string& frames,
                                const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"render", scene.string(), "--out", out.string(), "--frames", frames,
                                   "--width", "32", "--height", "32"};
  args.insert(args.end(), extra.begin(), extra.end());
  return test::run_pyro(args);
}

TEST(PyroCliRunIdentity, AnEditedSceneIsDrawnAgainOnResumeAndCounted) {
  const fs::path dir = test::scratch_dir("identity_edited_scene");
  const fs::path scene = dir / "fog.json", out = dir / "out", fresh = dir / "fresh";
  write_edited_scene("fog.json", scene, [](nlohmann::json&) {});
  ASSERT_EQ(render_file(scene, out, "3").exit_code, 0);
  const auto old_frames = contents(out);

  write_edited_scene("fog.json", scene, [](nlohmann::json& j) { j["background"] = {0.1, 0.2, 0.3}; });
  const auto resumed = render_file(scene, out, "3", {"--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("replacing 3 file(s)"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("the scene"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("resuming: 0 of 3"), std::string::npos) << resumed.err;
  ASSERT_EQ(render_file(scene, fresh, "3").exit_code, 0);
  for (const char* f : {"frame_0000.png", "frame_0001.png", "frame_0002.png"}) {
    EXPECT_NE(read_bytes(out / f), old_frames.at(f)) << f << " is the old scene's";
    EXPECT_EQ(read_bytes(out / f), read_bytes(fresh / f)) << f << " differs from a fresh render";
  }
}

TEST(PyroCliRunIdentity, AnEditedSceneReplacesItsEarlierRenderInItsOwnFolder) {
  const fs::path dir = test::scratch_dir("identity_rerender");
  const fs::path scene = dir / "fog.json", out = dir / "out", fresh = dir / "fresh";
  write_edited_scene("fog.json", scene, [](nlohmann::json&) {});
  ASSERT_EQ(render_file(scene, out, "3").exit_code, 0);
  // Saved by an editor that writes a new file and renames it over the old one.
  write_edited_scene("fog.json", dir / "fog.json.new",
                     [](nlohmann::json& j) { j["background"] = {0.1, 0.2, 0.3}; });
  fs::rename(dir / "fog.json.new", scene);
  const auto again = render_file(scene, out, "2");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("an earlier render of " + scene.string()), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("differs from this one in the scene"), std::string::npos) << again.err;
  ASSERT_EQ(render_file(scene, fresh, "2").exit_code, 0);
  EXPECT_EQ(contents(out), contents(fresh)) << "the earlier render's third frame goes too";

  // Another scene file, or the folder holding something else, is refused as before.
  write_edited_scene("fog.json", dir / "copy.json", [](nlohmann::json& j) { j["background"] = {0, 0, 1}; });
  const auto other_file = render_file(dir / "copy.json", out, "2");
  EXPECT_EQ(other_file.exit_code, 2) << other_file.err;
  write_text_pyro_cli_run_identity(out / "notes.txt", "the artist's notes");
  write_edited_scene("fog.json", scene, [](nlohmann::json& j) { j["background"] = {0.3, 0.2, 0.1}; });
  const auto with_notes = render_file(scene, out, "2");
  EXPECT_EQ(with_notes.exit_code, 2) << with_notes.err;
  EXPECT_EQ(contents(out).at("frame_0000.png"), contents(fresh).at("frame_0000.png"))
      << "a refusal changes nothing";
}

TEST(PyroCliRunIdentity, ADamagedOrSwappedFrameIsDrawnAgainOnResume) {
  const fs::path dir = test::scratch_dir("identity_damaged_frame");
  const fs::path out = dir / "out", fresh = dir / "fresh";
  ASSERT_EQ(test::render("fog.json", out, "4", 32).exit_code, 0);
  ASSERT_EQ(test::render("fog.json", fresh, "4", 32).exit_code, 0);
  fs::resize_file(out / "frame_0001.png", fs::file_size(out / "frame_0001.png") / 2);
  fs::copy_file(out / "frame_0000.png", out / "frame_0003.png", fs::copy_options::overwrite_existing);
  const auto resumed = test::render("fog.json", out, "4", 32, {"--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("2 frame file(s) of " + out.string() + " are damaged"), std::string::npos)
      << resumed.err;
  EXPECT_NE(resumed.err.find("resuming: 2 of 4"), std::string::npos) << resumed.err;
  EXPECT_EQ(contents(out), contents(fresh)) << "every frame has the bytes of a fresh render";
}

TEST(PyroCliRunIdentity, AnAssetReplacedInPlaceIsDrawnAgainOnResume) {
  const fs::path dir = test::scratch_dir("identity_edited_asset");
  const fs::path scene = dir / "cloud.json", asset = dir / "cloud.pyrop", out = dir / "out";
  fs::copy_file(content_path("volumes/sample_cloud_fitted.pyrop"), asset);
  write_edited_scene("cloud_fitted.json", scene,
                     [](nlohmann::json& j) { j["volumes"][0]["file"] = "cloud.pyrop"; });
  ASSERT_EQ(render_file(scene, out, "2").exit_code, 0);
  const std::string frame = read_bytes(out / "frame_0001.png");

  // The unchanged asset: everything is kept.
  const auto kept = render_file(scene, out, "2", {"--resume"});
  ASSERT_EQ(kept.exit_code, 0) << kept.err;
  EXPECT_NE(kept.err.find("resuming: 2 of 2"), std::string::npos) << kept.err;

  ParticleFile pf = read_particle_file(asset.string());
  ASSERT_FALSE(pf.anisotropic.empty());
  for (AnisotropicGaussian& g : pf.anisotropic) g.extinction *= 0.25f;
  write_particle_file(asset.string(), pf);
  const auto resumed = render_file(scene, out, "2", {"--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("replacing 2 file(s)"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("the asset at /volumes/0"), std::string::npos) << resumed.err;
  EXPECT_NE(read_bytes(out / "frame_0001.png"), frame) << "the old cloud kept";
}

TEST(PyroCliRunIdentity, AReformattedSceneIsTheSameRun) {
  const fs::path dir = test::scratch_dir("identity_reformatted");
  const fs::path scene = dir / "fog.json", out = dir / "out";
  write_edited_scene("fog.json", scene, [](nlohmann::json&) {});
  ASSERT_EQ(render_file(scene, out, "0:1").exit_code, 0);
  // Other spacing, another file name: the same scene as parsed adds its range to the folder.
  const fs::path moved = dir / "renamed.json";
  write_text_pyro_cli_run_identity(moved, nlohmann::json::parse(read_bytes(scene)).dump());
  const auto more = render_file(moved, out, "2:3");
  ASSERT_EQ(more.exit_code, 0) << more.err;
  EXPECT_EQ(contents(out).size(), 5u) << "four frames and the manifest";
}

TEST(PyroCliRunIdentity, AnotherRunIsRefusedAndOverwriteKeepsForeignFiles) {
  const fs::path dir = test::scratch_dir("identity_refused");
  const fs::path out = dir / "out";
  ASSERT_EQ(test::render("fog.json", out, "2", 32).exit_code, 0);
  write_text_pyro_cli_run_identity(out / "notes.txt", "the artist's notes");
  write_text_pyro_cli_run_identity(out / "frame_9999.png", "not written by pyro");
  const auto before = contents(out);

  const auto refused = test::render("mist.json", out, "1", 32);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("the scene"), std::string::npos) << refused.err;
  EXPECT_EQ(contents(out), before) << "a refusal changes nothing";

  const auto settings = test::render("fog.json", out, "1", 24);
  EXPECT_EQ(settings.exit_code, 2) << settings.err;
  EXPECT_NE(settings.err.find("width 32 -> 24"), std::string::npos) << settings.err;

  const auto replaced = test::render("mist.json", out, "1", 32, {"--overwrite"});
  ASSERT_EQ(replaced.exit_code, 0) << replaced.err;
  const auto after = contents(out);
  EXPECT_EQ(after.count("frame_0001.png"), 0u) << "the fog run's second frame is removed";
  EXPECT_NE(after.at("frame_0000.png"), before.at("frame_0000.png"));
  EXPECT_EQ(after.at("notes.txt"), "the artist's notes");
  EXPECT_EQ(after.at("frame_9999.png"), "not written by pyro");
}

// `pyro render -` reads the scene from standard input; bash's <(...) passes a pipe's path.
int render_piped(const std::string& scene, const fs::path& out, const std::string& how) {
  const std::string scene_file = test::shell_quote(test::scene_path(scene));
  const std::string pyro = test::shell_quote(test::pyro_binary());
  const std::string rest = " --out " + test::shell_quote(out.string()) + " --width 24 --height 24 2>/dev/null";
  const char* preload = std::getenv("LD_PRELOAD");  // for pyro alone: test_paths.h
  const std::string for_pyro = preload && *preload ? "env LD_PRELOAD=" + test::shell_quote(preload) + " " : "";
  const std::string cmd =
      how == "stdin" ? pyro + " render -" + rest + " < " + scene_file
                     : "env -u LD_PRELOAD bash -c " +
                           test::shell_quote(for_pyro + pyro + " render <(cat " + scene_file + ")" + rest);
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(PyroCliRunIdentity, PipedScenesAreKeyedOnWhatTheySay) {
  const fs::path dir = test::scratch_dir("identity_piped");
  for (const std::string how : {"stdin", "process-substitution"}) {
    const fs::path out = dir / how;
    EXPECT_EQ(render_piped("fog.json", out, how), 0) << how;
    EXPECT_EQ(render_piped("fog.json", out, how), 0) << how << ": the same scene again";
    EXPECT_EQ(render_piped("mist.json", out, how), 2) << how << ": mist into the fog's folder";
  }
  // The same scene from a pipe and from its file is one run.
  ASSERT_EQ(test::render("fog.json", dir / "stdin", "1", 24).exit_code, 0);
}

}  // namespace
}  // namespace pyro
