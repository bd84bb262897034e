// Progress bars on long work: drawn on a terminal, never into pipes or logs. The bar itself is
// checked on a file standing in for the terminal; the commands are run with stderr a pipe (no bar
// at all: no '\r') and under a pseudo-terminal from util-linux's `script` (the bar appears).
#include "tools/pyro/progress.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "engine/core/content_path.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  char buf[4096];
  size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
  return s;
}

size_t count_progress(const std::string& s, char c) { return size_t(std::count(s.begin(), s.end(), c)); }

TEST(Progress, DisabledWritesNothing) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    cli::Progress p("work", 10, false, f);
    for (size_t i = 0; i <= 10; ++i) p.stage(i, "stage " + std::to_string(i));
  }
  EXPECT_EQ(contents(f), "");
  std::fclose(f);
}

TEST(Progress, EnabledDrawsInPlaceThrottledAndEndsTheLine) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    cli::Progress p("render fog", 1000, true, f);
    for (size_t i = 1; i <= 1000; ++i) p.update(i);  // far faster than ten draws a second
  }
  const std::string out = contents(f);
  std::fclose(f);
  // The first draw, perhaps one more if the machine stalled for 100 ms, and the last.
  EXPECT_GE(count_progress(out, '\r'), 2u);
  EXPECT_LE(count_progress(out, '\r'), 12u);
  EXPECT_EQ(count_progress(out, '\n'), 1u);
  EXPECT_EQ(out.back(), '\n');
  EXPECT_NE(out.find("render fog [" + std::string(30, '#') + "] 1000/1000"), std::string::npos) << out;
}

TEST(Progress, StagesAreNamedAndAlwaysDrawn) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    cli::Progress p("import-vdb cloud.vdb", 4, true, f);
    p.stage(0, "read");
    p.stage(1, "import");
    p.stage(2, "light");
    p.update(4);
  }
  const std::string out = contents(f);
  std::fclose(f);
  EXPECT_EQ(count_progress(out, '\r'), 4u) << out;  // every stage change, and the end
  EXPECT_NE(out.find("0/4"), std::string::npos);
  EXPECT_NE(out.find("(read)"), std::string::npos);
  EXPECT_NE(out.find("(import)"), std::string::npos);
  EXPECT_NE(out.find("(light)"), std::string::npos);
  EXPECT_NE(out.find("[" + std::string(15, '#') + std::string(15, '.') + "] 2/4"), std::string::npos) << out;
  EXPECT_NE(out.find("4/4"), std::string::npos);
}

// The long commands, small.
std::vector<std::vector<std::string>> long_commands(const fs::path& dir) {
  return {
      {"render", test::scene_path("explosion.json"), "--width", "32", "--height", "32", "--frames",
       "3", "--out", (dir / "frames").string()},
      {"import-vdb", content_path("volumes/sample_cloud.vdb"), "--width", "32", "--height", "32",
       "--out", (dir / "cloud.pyrop").string()},
      {"bench", "layers", test::scene_path("explosion.json"), "--width", "32", "--height", "32",
       "--frames", "2", "--json"},
      {"analyze", "projection-error", "--surface", "all", "--grid", "5", "--csv-only", "--out",
       (dir / "figures").string()},
  };
}

TEST(Progress, CommandsDrawNoBarIntoAPipe) {
  const fs::path dir = test::scratch_dir("pipe");
  for (const auto& args : long_commands(dir)) {
    const auto r = test::run_pyro(args);  // stdout and stderr are files here, not terminals
    ASSERT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
    EXPECT_EQ(r.err.find('\r'), std::string::npos) << args[0] << ": " << r.err;
    EXPECT_EQ(r.err.find("[###"), std::string::npos) << args[0] << ": " << r.err;
    EXPECT_EQ(r.out.find('\r'), std::string::npos) << args[0];
  }
}

TEST(Progress, CommandsDrawTheBarOnATerminal) {
  if (std::system("command -v script >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "util-linux's `script` is not installed: no pseudo-terminal to run under";
  const fs::path dir = test::scratch_dir("tty");
  for (const auto& args : long_commands(dir)) {
    std::string command = test::shell_quote(test::pyro_binary());
    for (const std::string& a : args) command += " " + test::shell_quote(a);
    // A sanitizer preload (the asan-ubsan preset) is kept for pyro only, not for script itself.
    std::string unpreload;
    if (const char* preload = std::getenv("LD_PRELOAD"); preload && *preload) {
      command = "env LD_PRELOAD=" + test::shell_quote(preload) + " " + command;
      unpreload = "env -u LD_PRELOAD ";
    }
    // script runs the command on a new pseudo-terminal (its stdout and stderr) and copies what it
    // wrote to its own stdout; -e passes the command's exit status on.
    const fs::path log = dir / "typescript.txt";
    const std::string line = unpreload + "script -qec " + test::shell_quote(command) + " /dev/null > " +
                             test::shell_quote(log.string()) + " 2>&1 </dev/null";
    const int status = std::system(line.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << args[0] << ": " << line;
    std::ifstream in(log);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string out = ss.str();
    EXPECT_NE(out.find('\r'), std::string::npos) << args[0] << ": " << out;
    EXPECT_NE(out.find("[#"), std::string::npos) << args[0] << ": " << out;
    EXPECT_NE(out.find("#]"), std::string::npos) << args[0] << ": " << out;  // and it finished
  }
}

}  // namespace
}  // namespace pyro
