#include "engine/io/rename_fault.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>

namespace pyro {

void before_output_rename() {
  static const long kill_at = [] {
    const char* v = std::getenv("PYRO_TEST_KILL_BEFORE_RENAME");
    return v ? std::strtol(v, nullptr, 10) : 0L;
  }();
  static std::atomic<long> renames{0};
  if (++renames == kill_at) ::kill(::getpid(), SIGKILL);
}

}  // namespace pyro
