// One table of exit statuses for every command (docs/cli.md, "Exit status";
// tools/pyro/command_line.h): 0 success, 1 the environment or I/O, 2 the user's input, 3 no
// usable OpenGL, 130/143 the signals. Every command `pyro --help` lists is checked for 2 on an
// unknown option (with a suggestion); every command with --json for 1 when standard output is
// /dev/full.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/cli_render.h"
#include "tests/support/spawn_pyro.h"
#include "tests/support/test_paths.h"
#include "tools/pyro/app.h"
#include "tools/pyro/command_line.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// Every command path of the CLI app that runs something ("render", "bench scale", ...).
void collect_commands(CLI::App* app, const std::string& prefix, std::vector<std::string>& out) {
  for (CLI::App* sub : app->get_subcommands({})) {
    const std::string path = prefix.empty() ? sub->get_name() : prefix + " " + sub->get_name();
    if (sub->get_subcommands({}).empty())
      out.push_back(path);
    else
      collect_commands(sub, path, out);
  }
}

std::vector<std::string> all_commands() {
  CLI::App app;
  cli::add_pyro_commands(app);
  std::vector<std::string> commands;
  collect_commands(&app, "", commands);
  return commands;
}

bool has_json_flag(const std::string& command) {
  CLI::App app;
  cli::add_pyro_commands(app);
  CLI::App* at = &app;
  std::string word;
  for (std::istringstream words(command); words >> word;) at = at->get_subcommand(word);
  return at->get_option_no_throw("--json") != nullptr;
}

std::vector<std::string> words_of_pyro_cli_exit_status(const std::string& command) {
  std::vector<std::string> words;
  std::string w;
  for (std::istringstream in(command); in >> w;) words.push_back(w);
  return words;
}

// The exit-status table lives in docs/cli.md, which documents every command the tests below
// walk (a command added without its section fails here).
TEST(PyroCliExitStatus, TheCliDocumentsTheTableAndEveryCommand) {
  const std::string doc = test::read_bytes(fs::path(content_dir()) / ".." / "docs" / "cli.md");
  ASSERT_FALSE(doc.empty());
  for (const char* row : {"| 0 |", "| 1 |", "| 2 |", "| 3 |", "| 130, 143 |"})
    EXPECT_NE(doc.find(row), std::string::npos) << row;
  for (const std::string& command : all_commands())
    EXPECT_NE(doc.find("pyro " + words_of_pyro_cli_exit_status(command).front()), std::string::npos) << command;
}

// 2: an unknown option, for every command, named with the closest option.
TEST(PyroCliExitStatus, EveryCommandRefusesAnUnknownOptionWithTwo) {
  for (const std::string& command : all_commands()) {
    std::vector<std::string> args = words_of_pyro_cli_exit_status(command);
    args.push_back("--jsno");
    const auto r = test::run_pyro(args);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_EQ(r.err.rfind("pyro: error: unknown option '--jsno' for 'pyro " + command + "'", 0), 0u)
        << command << ": " << r.err;
    if (has_json_flag(command)) {
      EXPECT_NE(r.err.find("did you mean '--json'?"), std::string::npos) << command << ": " << r.err;
    }
  }
}

TEST(PyroCliExitStatus, UnknownCommandsGetASuggestion) {
  auto r = test::run_pyro({"rendr", "x"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "pyro: error: unknown command 'rendr' for 'pyro'; did you mean 'render'? (see 'pyro --help')\n");
  r = test::run_pyro({"bench", "scael"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("did you mean 'scale'?"), std::string::npos) << r.err;
}

TEST(PyroCliExitStatus, MessagesHaveNoEmptyFields) {
  const fs::path dir = test::scratch_dir("exit_status_fields");
  const auto r = test::run_pyro({"import-vdb", content_path("volumes/sample_cloud.vdb"), "--error", "0", "--out",
                                 (dir / "x.pyrop").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "pyro: error: at --error: a number in (0, 1], found 0\n");
}

// The cheapest run of each command that has --json, for the /dev/full check.
const std::map<std::string, std::vector<std::string>>& cheap_json_runs() {
  static const std::map<std::string, std::vector<std::string>> runs = {
      {"render", {"render", test::scene_path("fog.json"), "--out", "{dir}/render", "--width", "16", "--height", "16"}},
      {"bake-flipbook", {"bake-flipbook", test::scene_path("flipbook_fire.json"), "--out", "{dir}/flipbook",
                         "--frames", "2", "--loop-blend", "0", "--width", "16", "--height", "16"}},
      {"profile", {"profile", test::scene_path("fog.json"), "--frames", "2", "--width", "16", "--height", "16"}},
      {"quality", {"quality", test::scene_path("fog.json"), "--max-rmse", "0.5", "--width", "16", "--height", "16",
                   "--no-verify", "--no-cache"}},
      {"import-vdb", {"import-vdb", content_path("volumes/sample_cloud.vdb"), "--list"}},
      {"export-vdb", {"export-vdb", test::scene_path("fog.json"), "--out", "{dir}/vdb", "--voxel-size", "0.3"}},
      {"chart", {"chart", "footprint", "--out", "{dir}/chart", "--csv-only"}},
      {"analyze footprint", {"analyze", "footprint", "--size", "8"}},
      {"analyze projection-error", {"analyze", "projection-error", "--cx", "0", "--cy", "0", "--cz", "-5",
                                    "--radius", "0.4", "--near", "1"}},
      {"analyze billboard-modes", {"analyze", "billboard-modes", test::scene_path("fog.json"), "--width", "16",
                                   "--height", "16", "--frames", "1"}},
      {"analyze stereo", {"analyze", "stereo", "--samples", "2"}},
      {"analyze blackbody", {"analyze", "blackbody"}},
      {"analyze phase", {"analyze", "phase", "--cos-intervals", "8", "--azimuth-steps", "2"}},
      {"analyze flipbook-pattern", {"analyze", "flipbook-pattern", "--frames", "2"}},
      {"analyze six-way", {"analyze", "six-way", "--frame", "0", "--width", "4", "--height", "6"}},
      {"bench ecs", {"bench", "ecs", "--entities", "10", "--repeats", "1"}},
      {"bench sort", {"bench", "sort", "--count", "10", "--repeats", "1"}},
      {"bench scale", {"bench", "scale", test::scene_path("clouds.json"), "--counts", "100", "--frames", "1",
                       "--width", "16", "--height", "16"}},
      {"bench render", {"bench", "render", test::scene_path("fog.json"), "--width", "16", "--height", "16",
                        "--frames", "1", "--repeats", "1"}},
      {"bench layers", {"bench", "layers", test::scene_path("explosion.json"), "--width", "16", "--height", "16",
                        "--frames", "1", "--scales", "1"}},
      {"bench table1", {"bench", "table1", "--scene", test::scene_path("explosion.json"), "--frames", "1"}},
      {"bench soak", {"bench", "soak", test::scene_path("fog.json"), "--frames", "10", "--width", "16",
                      "--height", "16"}},
      {"bench schedule", {"bench", "schedule", test::scene_path("fog.json"), "--frames", "1", "--width", "16",
                          "--height", "16"}},
      {"bench johnson", {"bench", "johnson", "--frames", "2", "--width", "16", "--height", "16",
                         "--error-samples", "0"}},
      {"bench import-cases", {"bench", "import-cases", "--errors", "0.9", "--width", "16", "--height", "16"}},
      {"bench import-scale", {"bench", "import-scale", "--voxels", "1000"}},
      {"bench vdb-sequence", {"bench", "vdb-sequence", "--frames", "1", "--side", "8"}},
      {"bench vdb", {"bench", "vdb", content_path("volumes/sample_cloud.vdb"), "--error", "0.5", "--width", "16",
                     "--height", "16", "--vdb-render", "/bin/false"}},
      {"bench relight", {"bench", "relight", content_path("volumes/sample_cloud.vdb"), "--directions", "1",
                         "--width", "16", "--height", "16", "--frames", "1"}},
      {"bench multiple-scattering", {"bench", "multiple-scattering", content_path("volumes/sample_cloud.vdb"),
                                     "--directions", "1", "--samples", "2", "--width", "8", "--height", "8"}},
      {"bench cycles", {"bench", "cycles", content_path("volumes/sample_cloud.vdb"), "--directions", "1",
                        "--samples", "2", "--width", "8", "--height", "8", "--blender", "/bin/false"}},
      {"bench cycles-scene", {"bench", "cycles-scene", test::scene_path("fog.json"), "--width", "8", "--height", "8",
                              "--voxel-error", "0.5", "--blender", "/bin/false"}},
      {"bench cycles-fire", {"bench", "cycles-fire", content_path("volumes/sample_fire.vdb"), "--width", "8",
                             "--height", "8", "--blender", "/bin/false"}},
      {"bench export-vdb", {"bench", "export-vdb", test::scene_path("fog.json"), "--voxel-size", "0.3",
                            "--import-error", "0.5", "--width", "8", "--height", "8"}},
      {"bench explosion-shadows", {"bench", "explosion-shadows", content_path("scenes/explosion.json"), "--width", "16",
                                   "--height", "16", "--frames", "1", "--error-frames", "1"}},
  };
  return runs;
}

// 1: a result that cannot be written to standard output fails the command with the OS error.
TEST(PyroCliExitStatus, JsonIntoAFullDeviceIsOneForEveryCommand) {
  const fs::path dir = test::scratch_dir("exit_status_dev_full");
  for (const std::string& command : all_commands()) {
    if (!has_json_flag(command) || command == "view") continue;  // view: PyroView's own test
    const auto it = cheap_json_runs().find(command);
    ASSERT_NE(it, cheap_json_runs().end()) << command << " has --json: give it a cheap run here";
    std::vector<std::string> args;
    for (std::string a : it->second) {
      if (const auto at = a.find("{dir}"); at != std::string::npos) a.replace(at, 5, dir.string());
      args.push_back(a);
    }
    args.push_back("--json");
    std::string cmd = test::shell_quote(test::pyro_binary());
    for (const std::string& a : args) cmd += " " + test::shell_quote(a);
    cmd += " >/dev/full 2>" + test::shell_quote((dir / "err.txt").string()) + " </dev/null";
    const int status = std::system(cmd.c_str());
    const std::string err = test::read_bytes(dir / "err.txt");
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << command << ": " << err;
    EXPECT_NE(err.find("No space left on device"), std::string::npos) << command << ": " << err;
  }
  for (const char* flag : {"--version", "--help"}) {
    const auto r = test::run_pyro_with("", {flag});  // sanity: exit 0 where stdout is writable
    EXPECT_EQ(r.exit_code, 0) << flag;
    const int status = std::system((test::shell_quote(test::pyro_binary()) + " " + flag + " >/dev/full 2>/dev/null").c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << flag;
  }
}

TEST(PyroCliExitStatus, NoUsableOpenGlIsThree) {
  const auto r = test::run_pyro_with("env __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/egl_vendor.json",
                                     {"render", test::scene_path("fog.json"), "--out",
                                      (test::scratch_dir("exit_status_no_gl") / "out").string()});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(r.err.rfind("pyro: error: no usable OpenGL context", 0), 0u) << r.err;
}

// A frame is finished in the render's staging folder: the render loop runs.
bool drawing(const fs::path& out) {
  std::error_code ec;
  for (fs::directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().rfind(".partial-", 0) == 0)
      for (fs::directory_iterator f(it->path(), ec); !ec && f != end; f.increment(ec))
        if (f->path().extension() == ".png") return true;
  return false;
}

// 130 and 143: a signal mid-render unwinds, so the folder it created is gone with its staging.
TEST(PyroCliExitStatus, SignalsEndARenderCleanlyWith128PlusTheSignal) {
  for (const int sig : {SIGINT, SIGTERM}) {
    const fs::path dir = test::scratch_dir("exit_status_signal_" + std::to_string(sig));
    const fs::path out = dir / "out";
    const pid_t pid = test::spawn_pyro(test::render_args("fog.json", out, "400", 64));
    // Once frames are being drawn, the signal.
    for (int i = 0; i < 1200 && !drawing(out); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_TRUE(drawing(out)) << "the render never drew a frame";
    ::kill(pid, sig);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status)) << "ended by the signal itself, not by pyro";
    EXPECT_EQ(WEXITSTATUS(status), 128 + sig);
    EXPECT_FALSE(fs::exists(out)) << "the folder the run created, with its staging, is removed";
  }
}

}  // namespace
}  // namespace pyro
