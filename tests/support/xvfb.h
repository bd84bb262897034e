#pragma once
// Running `pyro view` under a virtual X server (xvfb-run; tools/install-deps.sh installs it).
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "tests/support/test_paths.h"

namespace pyro::test {

inline bool have_xvfb_run() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

// xvfb-run starting its display search at a number of this process's own (tests run in parallel),
// with a 24-bit screen. A sanitizer preload (the asan-ubsan preset) is kept for pyro only. Its
// authority file is this process's own (-f): without one, xvfb-run makes a temporary folder of
// its own and exits 5, whatever pyro returned, when it cannot remove it afterwards.
inline std::string xvfb_launcher() {
  const int first_display = 100 + int(getpid() % 800);
  const std::string auth = (scratch_dir("xvfb") / "Xauthority").string();
  std::string launcher = "xvfb-run -a -n " + std::to_string(first_display) + " -f " + shell_quote(auth) +
                         " -s '-screen 0 1024x768x24 -nolisten tcp'";
  if (const char* preload = std::getenv("LD_PRELOAD"); preload && *preload)
    launcher = "env -u LD_PRELOAD " + launcher + " env LD_PRELOAD=" + shell_quote(preload);
  return launcher;
}

}  // namespace pyro::test
