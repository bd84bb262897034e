#pragma once
// Paths the tests need: the pyro binary, the content folder, a scratch folder.
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/content_path.h"

namespace pyro::test {

// The pyro the tests run: the build's, or $PYRO_TEST_BINARY (to see the command-line tests
// fail on another build, an older one say).
inline std::string pyro_binary() {
  const char* other = std::getenv("PYRO_TEST_BINARY");
  return other && *other ? other : PYRO_BINARY;
}
inline std::string scene_path(const std::string& name) { return content_path("scenes/" + name); }

// A fresh empty folder under the system's temp folder, unique to this test.
std::filesystem::path scratch_dir(const std::string& name);

struct CommandResult {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};
// Runs `pyro` with the given arguments (each shell-quoted here).
CommandResult run_pyro(const std::vector<std::string>& args);
// Runs `pyro` behind a launcher: `launcher` is shell text put before the binary as is (e.g.
// "env -u DISPLAY" or an xvfb-run line); the arguments are quoted.
CommandResult run_pyro_with(const std::string& launcher, const std::vector<std::string>& args);
// `tool` (shell text, e.g. "timeout 20") run without this process's LD_PRELOAD, which then
// applies to pyro alone: a sanitizer preload (the asan-ubsan preset) would otherwise check the
// tool's own leaks at its exit and replace pyro's exit status with its report's.
std::string preload_for_pyro_only(const std::string& tool);
// Quotes `s` for the shell.
std::string shell_quote(const std::string& s);

}  // namespace pyro::test
