// No command overwrites its own inputs, and inputs that are not regular files are refused at
// once with what they are: every output path is compared with every input by file identity
// before any work (engine/io/output_gate.h), and a FIFO, folder or link loop where a file is
// expected is named as such (engine/core/file_kind.h).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/io/vdb_reader.h"
#include "tests/support/cli_render.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;
using test::read_bytes;

void write_text_pyro_cli_inputs(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

TEST(PyroCliInputs, ImportOverItsOwnVdbIsRefusedBeforeAnyWork) {
  const fs::path dir = test::scratch_dir("inputs_import");
  const fs::path vdb = dir / "box.vdb";
  fs::copy_file(content_path("volumes/sample_cloud.vdb"), vdb);
  const std::string before = read_bytes(vdb);
  auto r = test::run_pyro({"import-vdb", vdb.string(), "--out", vdb.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the VDB file being imported"), std::string::npos) << r.err;
  // Through a symbolic link: the same file.
  fs::create_symlink(vdb, dir / "link.pyrop");
  r = test::run_pyro({"import-vdb", vdb.string(), "--out", (dir / "link.pyrop").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(read_bytes(vdb), before);
}

// A damaged VDB: had the import started, its error would name the file's damage, not --out.
TEST(PyroCliInputs, ImportDestinationsAreCheckedBeforeTheImport) {
  const fs::path dir = test::scratch_dir("inputs_import_destination");
  const fs::path vdb = dir / "damaged.vdb";
  write_text_pyro_cli_inputs(vdb, "not a vdb at all");
  auto r = test::run_pyro({"import-vdb", vdb.string(), "--out", (dir / "missing" / "x.pyrop").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("at --out: an existing folder"), std::string::npos) << r.err;
  fs::create_directory(dir / "folder.pyrop");
  r = test::run_pyro({"import-vdb", vdb.string(), "--out", (dir / "folder.pyrop").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("found a folder"), std::string::npos) << r.err;
}

TEST(PyroCliInputs, ImportRemovesWhatKilledRunsLeft) {
  const fs::path dir = test::scratch_dir("inputs_import_leftovers");
  const fs::path out = dir / "cloud.pyrop";
  write_text_pyro_cli_inputs(dir / "cloud.pyrop.partial-999999999", "cut short by a kill");  // no such process
  const auto r = test::run_pyro({"import-vdb", content_path("volumes/sample_cloud.vdb"), "--out",
                                 out.string(), "--error", "0.2", "--width", "48", "--height", "48"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("removed 1 temporary file(s)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "cloud.pyrop.partial-999999999"));
  EXPECT_TRUE(fs::exists(out));
}

TEST(PyroCliInputs, TraceOverTheSceneOrIntoTheFramesIsRefused) {
  const fs::path dir = test::scratch_dir("inputs_trace");
  const fs::path scene = dir / "fog.json", out = dir / "out";
  fs::copy_file(test::scene_path("fog.json"), scene);
  const std::string before = read_bytes(scene);
  for (const char* command : {"render", "profile"}) {
    std::vector<std::string> args = {command, scene.string(), "--trace", scene.string(), "--width", "24",
                                     "--height", "24"};
    if (std::string(command) == "render") args.insert(args.end(), {"--out", out.string()});
    const auto r = test::run_pyro(args);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("the scene file"), std::string::npos) << r.err;
    EXPECT_EQ(read_bytes(scene), before) << command;
  }
  ASSERT_EQ(test::render("fog.json", out, "1", 24).exit_code, 0);
  const auto frames = test::contents(out);
  const auto r = test::render("fog.json", out, "1", 24, {"--trace", (out / "frame_0000.png").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::contents(out), frames);
}

// A chart's --out that cannot be its folder is refused before the measuring (minutes for some).
TEST(PyroCliInputs, ChartDestinationsAreCheckedBeforeMeasuring) {
  const fs::path dir = test::scratch_dir("inputs_chart");
  write_text_pyro_cli_inputs(dir / "a_file", "not a folder");
  for (const fs::path& out : {dir / "a_file", dir / "a_file" / "sub"}) {
    const auto r = test::run_pyro({"chart", "layer-resolution", "--out", out.string()});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("at --out"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("found a file"), std::string::npos) << r.err;
  }
}

// A FIFO that no program writes to would block an open forever: refused within a second.
TEST(PyroCliInputs, AFifoSceneIsRefusedAtOnce) {
  const fs::path dir = test::scratch_dir("inputs_fifo");
  const fs::path fifo = dir / "scene.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const std::vector<std::vector<std::string>> commands = {
      {"render", fifo.string(), "--out", (dir / "out").string()},
      {"bake-flipbook", fifo.string(), "--out", (dir / "flipbook").string()},
      {"quality", fifo.string()},
      {"profile", fifo.string()}};
  for (const auto& args : commands) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = test::run_pyro_with(test::preload_for_pyro_only("timeout 20"), args);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.err;
    EXPECT_NE(r.err.find("FIFO"), std::string::npos) << r.err;
    EXPECT_LT(seconds, 15.0) << args[0] << " waited on the FIFO";
  }
}

TEST(PyroCliInputs, VolumePathsThatAreNotFilesSayWhatTheyAre) {
  const fs::path dir = test::scratch_dir("inputs_volume_kinds");
  fs::create_directory(dir / "folder.vdb");
  ASSERT_EQ(::mkfifo((dir / "fifo.vdb").c_str(), 0644), 0);
  fs::create_symlink(dir / "loop_b.vdb", dir / "loop_a.vdb");
  fs::create_symlink(dir / "loop_a.vdb", dir / "loop_b.vdb");
  const std::pair<const char*, const char*> cases[] = {
      {"folder.vdb", "a folder"}, {"fifo.vdb", "a FIFO"}, {"loop_a.vdb", "a symbolic link loop"}};
  for (const auto& [file, kind] : cases) {
    const fs::path scene = dir / "scene.json";
    write_text_pyro_cli_inputs(scene, std::string(R"({"volumes": [{"file": ")") + file + "\"}]}");
    const std::string timeout = test::preload_for_pyro_only("timeout 20");
    const auto r = test::run_pyro_with(timeout, {"render", scene.string(), "--out", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << file << ": " << r.err;
    EXPECT_NE(r.err.find(kind), std::string::npos) << r.err;
    const auto i = test::run_pyro_with(timeout, {"import-vdb", (dir / file).string(), "--list"});
    EXPECT_EQ(i.exit_code, 2) << file << ": " << i.err;
    EXPECT_NE(i.err.find(kind), std::string::npos) << i.err;
  }
}

// Bytes from a file reach the terminal escaped: an escape sequence in a scene key is printed as
// \x1b, not acted on.
TEST(PyroCliInputs, BytesFromFilesAreEscapedInMessages) {
  const fs::path dir = test::scratch_dir("inputs_escaped");
  const fs::path scene = dir / "scene.json";
  write_text_pyro_cli_inputs(scene, "{\"\\u001b[2Jcloudz\": 1}");
  const auto r = test::run_pyro({"render", scene.string(), "--out", (dir / "out").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << "a raw escape reached stderr";
  EXPECT_NE(r.err.find("\\x1b[2Jcloudz"), std::string::npos) << r.err;
}

// OpenVDB's own log (a second grid of the same name, here) reaches stderr as pyro's lines: each
// prefixed with pyro and the file, its colour dropped, its bytes escaped (the file name holds an
// escape byte).
TEST(PyroCliInputs, OpenVdbLogLinesArePrefixedAndEscaped) {
  const fs::path dir = test::scratch_dir("inputs_vdb_log");
  const fs::path vdb = dir / "two\x1b" "densities.vdb";
  VdbGridToWrite grid;
  grid.name = "density";
  grid.dims = {4, 4, 4};
  grid.values.assign(64, 0.5f);
  write_vdb_grids(vdb.string(), {grid, grid});
  const auto r = test::run_pyro({"import-vdb", vdb.string(), "--out", (dir / "out.pyrop").string(),
                                 "--width", "16", "--height", "16"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ((r.err + r.out).find('\x1b'), std::string::npos) << r.err << r.out;
  std::istringstream lines(r.err);
  int from_openvdb = 0;
  for (std::string line; std::getline(lines, line);) {
    EXPECT_EQ(line.rfind("pyro", 0), 0u) << "a line not prefixed: " << line;
    from_openvdb += line.find(": OpenVDB: ") != std::string::npos;
  }
  EXPECT_GT(from_openvdb, 0) << "OpenVDB said nothing of the second grid: " << r.err;
}

}  // namespace
}  // namespace pyro
