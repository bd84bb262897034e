// The scene format's `volumes[]`: parse errors of every kind (JSON pointer, the volume file named,
// did-you-mean), path resolution against the scene file's folder, the fallback.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include "engine/core/user_error.h"
#include "systems/runtime/scene/scene_loader.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

class SceneVolumes : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::scratch_dir("scene_volumes");
    fs::create_directories(dir_ / "scenes");
    fs::create_directories(dir_ / "volumes");
    std::ofstream(dir_ / "volumes" / "cloud.vdb") << "not read by the loader";
    std::ofstream(dir_ / "volumes" / "cloud.pyrop") << "not read by the loader";
    scene_ = (dir_ / "scenes" / "scene.json").string();
  }
  std::string with_volumes(const std::string& volumes) const {
    return "{\"volumes\": [" + volumes + "]}";
  }
  std::string expect_error(const std::string& volumes, const std::string& place,
                           std::initializer_list<std::string> fragments) const {
    try {
      parse_scene(with_volumes(volumes), scene_);
    } catch (const UserError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.file(), scene_) << what;
      EXPECT_EQ(e.place(), place) << what;
      for (const std::string& f : fragments)
        EXPECT_NE(what.find(f), std::string::npos) << "missing [" << f << "] in: " << what;
      return what;
    }
    ADD_FAILURE() << "no error for: " << volumes;
    return {};
  }
  fs::path dir_;
  std::string scene_;
};

TEST_F(SceneVolumes, ResolvesAgainstTheSceneFolderWithDefaults) {
  const SceneDescription s = parse_scene(with_volumes(R"({"file": "../volumes/cloud.vdb"})"), scene_);
  ASSERT_EQ(s.volumes.size(), 1u);
  const VolumeDescription& v = s.volumes[0];
  EXPECT_EQ(fs::path(v.path), (dir_ / "volumes" / "cloud.vdb").lexically_normal());
  EXPECT_EQ(v.kind, VolumeFileKind::vdb);
  EXPECT_FALSE(v.used_fallback);
  EXPECT_EQ(v.pointer, "/volumes/0");
  EXPECT_TRUE(v.anchor_center);
  EXPECT_FLOAT_EQ(v.scale, 1.0f);
  EXPECT_FLOAT_EQ(v.error, 0.03f);
  EXPECT_EQ(v.grid_index, -1);
}

TEST_F(SceneVolumes, UsesTheFallbackOnlyWhenTheFileIsAbsent) {
  SceneDescription s = parse_scene(
      with_volumes(R"({"file": "../missing/big.vdb", "fallback": "../volumes/cloud.pyrop", "size": 4})"),
      scene_);
  EXPECT_TRUE(s.volumes[0].used_fallback);
  EXPECT_EQ(s.volumes[0].kind, VolumeFileKind::particles);
  EXPECT_EQ(fs::path(s.volumes[0].path), (dir_ / "volumes" / "cloud.pyrop").lexically_normal());
  s = parse_scene(
      with_volumes(R"({"file": "../volumes/cloud.vdb", "fallback": "../volumes/cloud.pyrop"})"), scene_);
  EXPECT_FALSE(s.volumes[0].used_fallback);
  EXPECT_EQ(s.volumes[0].kind, VolumeFileKind::vdb);
}

TEST_F(SceneVolumes, MissingFilesNameTheResolvedPaths) {
  expect_error(R"({"file": "cloud.vdb"})", "/volumes/0/file",
               {"no file at", (dir_ / "scenes" / "cloud.vdb").string()});
  expect_error(R"({"file": "../volumes/cloud.vdb"}, {"file": "a.vdb", "fallback": "b.pyrop"})",
               "/volumes/1/file",
               {"neither", (dir_ / "scenes" / "a.vdb").string(), (dir_ / "scenes" / "b.pyrop").string()});
}

TEST_F(SceneVolumes, RefusesEveryKindOfMistake) {
  expect_error(R"({})", "/volumes/0", {"missing required key \"file\""});
  expect_error(R"(3)", "/volumes/0", {"expected an object describing a volume"});
  expect_error(R"({"file": "../volumes/cloud.txt"})", "/volumes/0/file", {".vdb", ".pyrop"});
  expect_error(R"({"file": ""})", "/volumes/0/file", {"found \"\""});
  expect_error(R"({"file": 7})", "/volumes/0/file", {"found 7"});
  expect_error(R"({"file": "../volumes/cloud.vdb", "fallback": "x.png"})", "/volumes/0/fallback", {".pyrop"});
  expect_error(R"({"file": "../volumes/cloud.vdb", "scael": 2})", "/volumes/0/scael",
               {"did you mean \"scale\""});
  expect_error(R"({"file": "../volumes/cloud.vdb", "scale": 0})", "/volumes/0/scale", {"(0, 1e6]"});
  expect_error(R"({"file": "../volumes/cloud.vdb", "scale": 2, "size": 3})", "/volumes/0/size",
               {"either \"scale\" or \"size\""});
  expect_error(R"({"file": "../volumes/cloud.vdb", "grid": "density", "grid_index": 1})",
               "/volumes/0/grid_index", {"either \"grid\" or \"grid_index\""});
  expect_error(R"({"file": "../volumes/cloud.vdb", "grid_index": -1})", "/volumes/0/grid_index",
               {"an integer in [0, 1000000]"});
  expect_error(R"({"file": "../volumes/cloud.vdb", "error": 0})", "/volumes/0/error", {"(0, 1]"});
  expect_error(R"({"file": "../volumes/cloud.vdb", "anchor": "centre"})", "/volumes/0/anchor",
               {"did you mean \"center\""});
  expect_error(R"({"file": "../volumes/cloud.vdb", "position": [1, 2]})", "/volumes/0/position",
               {"array of 3 numbers"});
  expect_error(R"({"file": "../volumes/cloud.pyrop", "grid": "density"})", "/volumes/0/grid",
               {"particle file (.pyrop)", "cloud.pyrop"});
}

TEST_F(SceneVolumes, ReadsTheFiresEmission) {
  const SceneDescription d = parse_scene(with_volumes(R"({"file": "../volumes/cloud.vdb"})"), scene_);
  EXPECT_TRUE(d.volumes[0].emission.automatic);
  EXPECT_FLOAT_EQ(d.volumes[0].emission.intensity, 4.0f);
  EXPECT_TRUE(d.volumes[0].temperature_grid.empty());
  const SceneDescription s = parse_scene(
      with_volumes(R"({"file": "../volumes/cloud.vdb", "temperature_grid": "flame",
                       "emission": {"temperature": {"scale": 1500, "offset": 1000}, "intensity": 3}},
                      {"file": "../volumes/cloud.pyrop",
                       "emission": {"temperature": {"table": [[0, 900], [0.5, 1800], [1, 2400]]}}})"),
      scene_);
  const VolumeEmissionDescription& a = s.volumes[0].emission;
  EXPECT_EQ(s.volumes[0].temperature_grid, "flame");
  EXPECT_FALSE(a.automatic);
  EXPECT_FLOAT_EQ(a.scale, 1500.0f);
  EXPECT_FLOAT_EQ(a.offset, 1000.0f);
  EXPECT_FLOAT_EQ(a.intensity, 3.0f);
  const VolumeEmissionDescription& b = s.volumes[1].emission;
  ASSERT_EQ(b.table.size(), 3u);
  EXPECT_FLOAT_EQ(b.table[1][0], 0.5f);
  EXPECT_FLOAT_EQ(b.table[2][1], 2400.0f);
}

TEST_F(SceneVolumes, RefusesEveryMistakeInTheFire) {
  const std::string vdb = R"("file": "../volumes/cloud.vdb", )";
  expect_error("{" + vdb + R"("emission": {"temperature": {"table": [[0, 900], [0, 1800]]}}})",
               "/volumes/0/emission/temperature/table/1/0", {"strictly ascending", "0 follows 0"});
  expect_error("{" + vdb + R"("emission": {"temperature": {"table": [[0, 900]]}}})",
               "/volumes/0/emission/temperature/table", {"2 to 1024"});
  expect_error("{" + vdb + R"("emission": {"temperature": {"table": [[0, 900], [1, -5]]}}})",
               "/volumes/0/emission/temperature/table/1/1", {"[0, 1e6]"});
  expect_error("{" + vdb + R"("emission": {"temperature": {"table": [[0, 900], [1, 2000]], "scale": 2}}})",
               "/volumes/0/emission/temperature/table", {"found both"});
  expect_error("{" + vdb + R"("emission": {"temperature": {}}})", "/volumes/0/emission/temperature",
               {"found neither"});
  expect_error("{" + vdb + R"("emission": {"intensity": -1}})", "/volumes/0/emission/intensity", {"[0, 1e6]"});
  expect_error("{" + vdb + R"("emission": {"intensty": 2}})", "/volumes/0/emission/intensty", {"intensity"});
  expect_error(R"({"file": "../volumes/cloud.pyrop", "temperature_grid": "heat"})", "/volumes/0/temperature_grid",
               {"OpenVDB"});
}

}  // namespace
}  // namespace pyro
