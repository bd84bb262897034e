#include "tests/support/test_paths.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

namespace pyro::test {

std::filesystem::path scratch_dir(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string tag = name;
  if (info) tag = std::string(info->test_suite_name()) + "_" + info->name() + "_" + name;
  const auto dir = std::filesystem::temp_directory_path() /
                   ("pyro_test_" + std::to_string(getpid()) + "_" + tag);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') q += "'\\''";
    else q += c;
  }
  return q + "'";
}

namespace {
std::string quote(const std::string& s) { return shell_quote(s); }
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

std::string preload_for_pyro_only(const std::string& tool) {
  const char* preload = std::getenv("LD_PRELOAD");
  if (!preload || !*preload) return tool;
  return "env -u LD_PRELOAD " + tool + " env LD_PRELOAD=" + quote(preload);
}

CommandResult run_pyro(const std::vector<std::string>& args) { return run_pyro_with("", args); }

CommandResult run_pyro_with(const std::string& launcher, const std::vector<std::string>& args) {
  const auto dir = scratch_dir("cmd");
  std::string cmd = launcher.empty() ? quote(pyro_binary()) : launcher + " " + quote(pyro_binary());
  for (const auto& a : args) cmd += " " + quote(a);
  cmd += " >" + quote((dir / "out.txt").string()) + " 2>" + quote((dir / "err.txt").string()) + " </dev/null";
  const int status = std::system(cmd.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / "out.txt");
  r.err = slurp(dir / "err.txt");
  std::filesystem::remove_all(dir);
  return r;
}

}  // namespace pyro::test
