// The hazard matrix: every command with an output, against every hazard an output path can meet
// (engine/io/output_gate.h; docs/reliability.md, "The gate"). For each pair the command exits
// with the status docs/cli.md gives, every file of the fixture keeps its bytes, and nothing is
// created. A command added with an output joins the table below.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "tests/support/scratch_mount.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;
using Args = std::vector<std::string>;

enum class Shape { file, folder, container };

// A command with one output path: how it is called with the output at `out`, the input an
// output may not be, and the folder it reads (if any) that an output may not be inside.
struct Command {
  std::string name;
  Shape shape;
  std::function<Args(const fs::path& fixture, const std::string& out)> args;
  std::string input;         // relative to the fixture; "" when it reads no file of the user's
  std::string input_folder;  // relative to the fixture; "" when it reads no folder
};

// The fixture every command reads: a scene with a fire whose flipbook is a folder beside it, a
// VDB file, a VDB sequence, a six-way bake and the smoke scene it was baked from.
const char* kScene = R"({
  "name": "hazards", "output": {"width": 32, "height": 24},
  "camera": {"position": [0, 0.5, 4], "target": [0, 0.5, 0]},
  "fires": [{"name": "f", "position": [0, 0, 0], "width": 0.5, "aspect": 1.5, "flipbook": "flame"}]
})";

std::string in_fixture(const fs::path& fixture, const std::string& name) { return (fixture / name).string(); }

std::vector<Command> commands() {
  const std::string flame_scene = content_path("scenes/flipbook_fire.json");
  const std::string smoke_scene = content_path("scenes/six_way_smoke.json");
  const Args small = {"--frames", "2", "--width", "8", "--height", "8", "--loop-blend", "0"};
  const auto bake = [small](const std::string& scene, Args extra) {
    return [scene, small, extra](const fs::path&, const std::string& out) {
      Args a = {"bake-flipbook", scene, "--out", out};
      a.insert(a.end(), small.begin(), small.end());
      a.insert(a.end(), extra.begin(), extra.end());
      return a;
    };
  };
  return {
      {"render --out", Shape::folder, [](const fs::path& f, const std::string& o) {
         return Args{"render", in_fixture(f, "scene.json"), "--out", o}; }, "scene.json", "flame"},
      {"render --trace", Shape::file, [](const fs::path& f, const std::string& o) {
         return Args{"render", in_fixture(f, "scene.json"), "--out", in_fixture(f, "frames"), "--trace", o}; }, "scene.json", "flame"},
      {"render --video", Shape::file, [](const fs::path& f, const std::string& o) {
         return Args{"render", in_fixture(f, "scene.json"), "--out", in_fixture(f, "frames"), "--video", o + ".mp4"}; }, "", "flame"},
      {"view --screenshot", Shape::file, [](const fs::path& f, const std::string& o) {
         return Args{"view", in_fixture(f, "scene.json"), "--frames", "1", "--screenshot", o}; }, "scene.json", "flame"},
      {"view --screenshot-at", Shape::file, [](const fs::path& f, const std::string& o) {
         return Args{"view", in_fixture(f, "scene.json"), "--frames", "1", "--screenshot-at", "0:" + o}; }, "scene.json", "flame"},
      {"view --save-as", Shape::file, [](const fs::path& f, const std::string& o) {
         return Args{"view", in_fixture(f, "scene.json"), "--frames", "1", "--save-as", o}; }, "scene.json", "flame"},
      {"profile --trace", Shape::file, [](const fs::path& f, const std::string& o) {
         return Args{"profile", in_fixture(f, "scene.json"), "--frames", "1", "--warmup", "0", "--trace", o}; }, "scene.json", "flame"},
      {"bake-flipbook", Shape::folder, bake(flame_scene, {}), "", ""},
      {"bake-flipbook --atlas", Shape::folder, bake(flame_scene, {"--atlas", "2x1"}), "", ""},
      {"bake-flipbook --six-way", Shape::folder, bake(smoke_scene, {"--six-way"}), "", ""},
      {"import-vdb FILE", Shape::file, [](const fs::path& f, const std::string& o) {
         return Args{"import-vdb", in_fixture(f, "cloud.vdb"), "--out", o, "--width", "16", "--height", "16"}; }, "cloud.vdb", ""},
      {"import-vdb SEQUENCE", Shape::folder, [](const fs::path& f, const std::string& o) {
         return Args{"import-vdb", in_fixture(f, "in.pyroseq"), "--out", o + ".pyroseq"}; }, "", "in.pyroseq"},
      {"export-vdb", Shape::folder, [](const fs::path& f, const std::string& o) {
         return Args{"export-vdb", in_fixture(f, "scene.json"), "--out", o}; }, "scene.json", "flame"},
      {"farm submit", Shape::folder, [](const fs::path& f, const std::string& o) {
         return Args{"farm", "submit", in_fixture(f, "scene.json"), "--out", o, "--frames", "2", "--chunk", "1", "--dry-run"}; }, "scene.json", "flame"},
      {"new", Shape::file, [](const fs::path&, const std::string& o) {
         return Args{"new", o, "--template", "clouds", "--force"}; }, "", ""},
      {"schema", Shape::file, [](const fs::path&, const std::string& o) {
         return Args{"schema", "--out", o}; }, "", ""},
      {"analyze six-way-relight", Shape::file, [](const fs::path& f, const std::string& o) {
         return Args{"analyze", "six-way-relight", in_fixture(f, "six"), "--image", o}; }, "six/six_way_a/frame_0000.png", "six"},
      {"analyze six-way --image", Shape::file, [](const fs::path&, const std::string& o) {
         return Args{"analyze", "six-way", "--width", "8", "--height", "8", "--image", o}; }, "", ""},
      {"analyze projection-error", Shape::container, [](const fs::path&, const std::string& o) {
         return Args{"analyze", "projection-error", "--surface", "all", "--out", o, "--csv-only"}; }, "", ""},
      {"chart", Shape::container, [](const fs::path&, const std::string& o) {
         return Args{"chart", "footprint", "--out", o, "--csv-only", "--frames", "1"}; }, "", ""},
      {"bench vdb-sequence --keep", Shape::container, [](const fs::path&, const std::string& o) {
         return Args{"bench", "vdb-sequence", "--keep", o, "--frames", "1"}; }, "", ""},
      {"bench import-scale --keep", Shape::file, [](const fs::path&, const std::string& o) {
         return Args{"bench", "import-scale", "--keep", o, "--voxels", "1000"}; }, "", ""},
      {"bench cycles-scene --image", Shape::file, [](const fs::path& f, const std::string& o) {
         return Args{"bench", "cycles-scene", in_fixture(f, "scene.json"), "--image", o, "--blender", "/nonexistent/blender"}; },
       "scene.json", "flame"},
      {"bench multiple-scattering --images", Shape::container, [](const fs::path& f, const std::string& o) {
         return Args{"bench", "multiple-scattering", in_fixture(f, "cloud.vdb"), "--images", o}; }, "", ""},
  };
}

// Every path under `dir` with its bytes ("" for what is not a regular file): what a hazard may
// not change.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (fs::recursive_directory_iterator it(dir), end; it != end; ++it) {
    std::string bytes;
    if (it->symlink_status().type() == fs::file_type::regular) {
      std::ifstream in(it->path(), std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    files[fs::relative(it->path(), dir).string()] = bytes;
  }
  return files;
}

class HazardMatrix : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fixture_ = new fs::path(test::scratch_dir("hazard_fixture"));
    const fs::path& f = *fixture_;
    std::ofstream(f / "scene.json") << kScene;
    fs::copy_file(content_path("volumes/sample_cloud.vdb"), f / "cloud.vdb");
    fs::create_directory(f / "in.pyroseq");
    for (int i = 1; i <= 2; ++i)
      fs::copy_file(f / "cloud.vdb", f / "in.pyroseq" / ("smoke_00000" + std::to_string(i) + ".vdb"));
    for (const auto& [scene, out, extra] :
         {std::tuple{content_path("scenes/flipbook_fire.json"), "flame", ""},
          std::tuple{content_path("scenes/six_way_smoke.json"), "six", "--six-way"}}) {
      Args a = {"bake-flipbook", scene, "--out", in_fixture(f, out), "--frames", "2", "--width", "8",
                "--height", "8", "--loop-blend", "0"};
      if (*extra) a.push_back(extra);
      const test::CommandResult r = run(a);
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    // Each hazard under the plain name and with the suffixes commands add (--video's, a sequence's).
    for (const char* suffix : {"", ".mp4", ".pyroseq"}) {
      const std::string s = suffix;
      fs::create_directory(f / ("user" + s));
      std::ofstream(f / ("user" + s) / "thesis.txt") << "precious";
      ASSERT_EQ(::mkfifo((f / ("fifo" + s)).c_str(), 0644), 0);
      device_ = ::mknod((f / ("null" + s)).c_str(), S_IFCHR | 0666, ::makedev(1, 3)) == 0;
    }
  }
  static void TearDownTestSuite() {
    delete fixture_;
    fixture_ = nullptr;
  }

  // pyro ARGS, never left waiting on a FIFO.
  static test::CommandResult run(const Args& args) {
    return test::run_pyro_with(test::preload_for_pyro_only("timeout 120"), args);
  }

  // `args` refused with `status` by a message that names `named` (the output path, so that a
  // refusal for another reason does not pass), the fixture as it was.
  static void expect_refused(const std::string& what, const Args& args, const std::string& named,
                             int status = 2) {
    const auto before = snapshot(*fixture_);
    const test::CommandResult r = run(args);
    EXPECT_EQ(r.exit_code, status) << what << "\n" << r.err;
    EXPECT_NE(r.err.find("pyro: error:"), std::string::npos) << what << "\n" << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << what << ": the message names " << named << "\n" << r.err;
    const auto after = snapshot(*fixture_);
    for (const auto& [path, bytes] : before) {
      const auto it = after.find(path);
      EXPECT_TRUE(it != after.end() && it->second == bytes) << what << ": " << path << " lost or changed";
    }
    for (const auto& [path, bytes] : after)
      EXPECT_TRUE(before.count(path)) << what << ": " << path << " created";
  }

  static fs::path* fixture_;
  static bool device_;
};

fs::path* HazardMatrix::fixture_ = nullptr;
bool HazardMatrix::device_ = false;

TEST_F(HazardMatrix, AnOutputIsNeverAnInput) {
  for (const Command& c : commands())
    if (!c.input.empty())
      expect_refused(c.name + " onto its input", c.args(*fixture_, in_fixture(*fixture_, c.input)), c.input);
}

TEST_F(HazardMatrix, AnOutputIsNeverInsideAFolderTheCommandReads) {
  for (const Command& c : commands())
    if (!c.input_folder.empty())
      expect_refused(c.name + " inside its input folder", c.args(*fixture_, in_fixture(*fixture_, c.input_folder + "/out")),
                     c.input_folder + "/out");
  // A folder output holding what the command reads.
  expect_refused("import-vdb SEQUENCE onto its own folder",
                 {"import-vdb", in_fixture(*fixture_, "in.pyroseq"), "--out", in_fixture(*fixture_, "in.pyroseq")}, "--out");
  expect_refused("import-vdb PATTERN into the members' folder",
                 {"import-vdb", in_fixture(*fixture_, "in.pyroseq/smoke_%06d.vdb"), "--out", in_fixture(*fixture_, "in.pyroseq")},
                 "--out");
  fs::create_directory(*fixture_ / "in.pyroseq" / "cache");
  fs::copy_file(*fixture_ / "cloud.vdb", *fixture_ / "in.pyroseq" / "cache" / "smoke_000001.vdb");
  expect_refused("import-vdb of a sub-folder into the folder above",
                 {"import-vdb", in_fixture(*fixture_, "in.pyroseq/cache"), "--out", in_fixture(*fixture_, "in.pyroseq")}, "--out");
  fs::remove_all(*fixture_ / "in.pyroseq" / "cache");
}

TEST_F(HazardMatrix, DeviceNodesAndFifosAreNeverReplaced) {
  for (const Command& c : commands()) {
    expect_refused(c.name + " onto a FIFO", c.args(*fixture_, in_fixture(*fixture_, "fifo")), "fifo");
    if (device_) expect_refused(c.name + " onto a device node", c.args(*fixture_, in_fixture(*fixture_, "null")), "null");
  }
  if (!device_) GTEST_SKIP() << "mknod needs root: the device-node half was not tried";
}

TEST_F(HazardMatrix, AFolderOfTheUsersIsNeverReplaced) {
  for (const Command& c : commands())
    if (c.shape != Shape::container)
      expect_refused(c.name + " onto a folder holding the user's file", c.args(*fixture_, in_fixture(*fixture_, "user")),
                     "user");
}

// A file output's folder must exist; a folder output creates its parents.
TEST_F(HazardMatrix, AMissingFolderIsNotCreated) {
  for (const Command& c : commands())
    if (c.shape == Shape::file)
      expect_refused(c.name + " into a missing folder", c.args(*fixture_, in_fixture(*fixture_, "missing/out")), "missing");
}

TEST_F(HazardMatrix, AReadOnlyFolderFailsBeforeTheWork) {
  test::ScratchMount mount(*fixture_ / "read_only", "size=64k", true);
  if (!mount.mounted()) GTEST_SKIP() << mount.why();
  for (const Command& c : commands()) {
    const std::string out = c.shape == Shape::container ? "read_only" : "read_only/out";  // written into
    expect_refused(c.name + " into a read-only folder", c.args(*fixture_, in_fixture(*fixture_, out)), "read_only", 1);
  }
}

TEST_F(HazardMatrix, TwoOutputsNeverShareAPath) {
  const fs::path& f = *fixture_;
  expect_refused("render --video X --trace X", {"render", in_fixture(f, "scene.json"), "--out", in_fixture(f, "frames"),
                                               "--video", in_fixture(f, "same.mp4"), "--trace", in_fixture(f, "same.mp4")},
                 "same.mp4");
  expect_refused("render --trace inside --out", {"render", in_fixture(f, "scene.json"), "--out", in_fixture(f, "frames"),
                                                 "--trace", in_fixture(f, "frames/trace.json")}, "trace.json");
  expect_refused("view --screenshot X --save-as X", {"view", in_fixture(f, "scene.json"), "--frames", "1",
                                                     "--screenshot", in_fixture(f, "same"), "--save-as", in_fixture(f, "same")},
                 "same");
  expect_refused("view --screenshot-at twice", {"view", in_fixture(f, "scene.json"), "--frames", "2", "--screenshot-at",
                                                "0:" + in_fixture(f, "shot.png"), "--screenshot-at", "1:" + in_fixture(f, "shot.png")},
                 "shot.png");
}

TEST_F(HazardMatrix, SizesTheReadersRefuseAreRefusedUpFront) {
  for (const char* grid : {"600x1", "1000x1000", "9999x9999"})
    expect_refused(std::string("bake-flipbook --atlas ") + grid,
                   {"bake-flipbook", content_path("scenes/flipbook_fire.json"), "--out", in_fixture(*fixture_, "atlas"),
                    "--atlas", grid, "--frames", "4", "--width", "32", "--height", "48", "--loop-blend", "0"},
                   "--atlas");
  expect_refused("bake-flipbook frames past the memory",
                 {"bake-flipbook", content_path("scenes/flipbook_fire.json"), "--out", in_fixture(*fixture_, "big"),
                  "--frames", "10000", "--width", "4096", "--height", "4096"},
                 "memory");
}

}  // namespace
}  // namespace pyro
