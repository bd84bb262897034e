// pyro export-vdb end to end: the files of a frame range named as Blender's and Houdini's
// sequence readers expect, their grids (density as a fog volume; temperature and colour where
// the explosion has fire and varying colours), the summary, and bad input refused with exit
// status 2 before anything is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

const char* kExportCliCloud = R"({
  "name": "small cloud", "output": {"width": 32, "height": 24},
  "camera": {"position": [0, 0, 6], "target": [0, 0, 0]},
  "clouds": [{"count": 30, "radius": 0.5, "density": 0.3, "jitter": 0.2, "box": {"min": [-1, -0.5, -1], "max": [1, 0.5, 1]}}]
})";

std::string export_cli_scene(const fs::path& dir) {
  const std::string path = (dir / "cloud.json").string();
  std::ofstream(path) << kExportCliCloud;
  return path;
}

// The grids of `file` as `pyro import-vdb --list --json` names them: "name type class" each.
std::vector<std::string> export_cli_grids(const fs::path& file) {
  const test::CommandResult r = test::run_pyro({"import-vdb", file.string(), "--list", "--json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> out;
  if (r.exit_code != 0) return out;
  const nlohmann::json listing = test::last_json_line(r.out);
  for (const auto& g : listing["grids"])
    out.push_back(g["name"].get<std::string>() + " " + g["value_type"].get<std::string>() + " " +
                  g["class"].get<std::string>());
  std::sort(out.begin(), out.end());  // the file's order is OpenVDB's
  return out;
}

TEST(ExportVdbCli, WritesOneFilePerFrameNumberedFromOne) {
  const fs::path dir = test::scratch_dir("export_vdb_cli_frames");
  const test::CommandResult r =
      test::run_pyro({"export-vdb", export_cli_scene(dir), "--out", (dir / "out").string(), "--frames", "2:4", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = test::last_json_line(r.out);
  EXPECT_EQ(j["pattern"], "small_cloud.####.vdb");
  EXPECT_EQ(j["files"], 3);
  EXPECT_TRUE(j["error_met"].get<bool>());
  EXPECT_LE(j["opacity_error_max"].get<double>(), 0.01);
  EXPECT_GT(j["voxel_size"].get<double>(), 0.0);
  for (const char* f : {"small_cloud.0003.vdb", "small_cloud.0004.vdb", "small_cloud.0005.vdb"})
    EXPECT_TRUE(fs::is_regular_file(dir / "out" / f)) << f;
  EXPECT_FALSE(fs::exists(dir / "out" / "small_cloud.0002.vdb"));
  EXPECT_EQ(export_cli_grids(dir / "out" / "small_cloud.0003.vdb"), std::vector<std::string>{"density float fog volume"});
}

TEST(ExportVdbCli, PrintsTheVoxelSizeAndTheErrorOnStdout) {
  const fs::path dir = test::scratch_dir("export_vdb_cli_text");
  const test::CommandResult r = test::run_pyro(
      {"export-vdb", export_cli_scene(dir), "--out", (dir / "out").string(), "--voxel-size", "0.05", "--name", "c"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("voxel size 0.05 (given)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("column opacity error"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "c.0001.vdb"));
}

TEST(ExportVdbCli, TheExplosionCarriesTemperatureAndColour) {
  const fs::path dir = test::scratch_dir("export_vdb_cli_fire");
  const test::CommandResult r = test::run_pyro({"export-vdb", test::scene_path("explosion.json"), "--out",
                                                (dir / "out").string(), "--frames", "6:6", "--error", "0.03", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = test::last_json_line(r.out);
  EXPECT_TRUE(j["frames"][0]["temperature"].get<bool>());
  EXPECT_LE(j["opacity_error_max"].get<double>(), 0.03);
  const std::vector<std::string> grids = export_cli_grids(dir / "out" / "explosion.0007.vdb");
  EXPECT_EQ(grids, (std::vector<std::string>{"color vec3s unknown", "density float fog volume",
                                             "temperature float fog volume"}));
}

TEST(ExportVdbCli, BadInputIsRefusedAndNothingIsWritten) {
  const fs::path dir = test::scratch_dir("export_vdb_cli_bad");
  const std::string scene = export_cli_scene(dir), out = (dir / "out").string();
  std::ofstream(dir / "broken.json") << "{\"name\": ";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"export-vdb", (dir / "missing.json").string(), "--out", out}, "missing.json"},
      {{"export-vdb", (dir / "broken.json").string(), "--out", out}, "broken.json"},
      {{"export-vdb", scene, "--out", out, "--frames", "5:2"}, "--frames"},
      {{"export-vdb", scene, "--out", out, "--frames", "x"}, "--frames"},
      {{"export-vdb", scene, "--out", out, "--error", "0"}, "--error"},
      {{"export-vdb", scene, "--out", out, "--voxel-size", "-1"}, "--voxel-size"},
      {{"export-vdb", scene, "--out", out, "--name", "a/b"}, "--name"},
      // A grid past the voxel limit is found at the first frame, before anything is written.
      {{"export-vdb", scene, "--out", out, "--voxel-size", "0.001"}, "--voxel-size"},
  };
  for (const auto& [args, named] : cases) {
    const test::CommandResult r = test::run_pyro(args);
    EXPECT_EQ(r.exit_code, 2) << args.back() << "\n" << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << named;
  }
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
  EXPECT_EQ(left.size(), 2u) << "only the two scenes: no staging folder left";
}

}  // namespace
}  // namespace pyro
