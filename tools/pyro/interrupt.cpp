#include "tools/pyro/interrupt.h"

#include <signal.h>
#include <unistd.h>

namespace pyro::cli {

namespace {

volatile sig_atomic_t g_signal = 0;
pid_t g_main_pid = 0;

void on_alarm(int) { _exit(128 + (g_signal != 0 ? g_signal : SIGTERM)); }

void on_signal(int sig) {
  if (g_signal != 0) _exit(128 + sig);  // the second signal: now
  g_signal = sig;
  alarm(3);  // work that never reaches a progress step ends all the same
}

}  // namespace

void install_interrupt_handlers() {
  g_main_pid = getpid();
  struct sigaction action {};
  sigemptyset(&action.sa_mask);
  action.sa_handler = on_signal;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  action.sa_handler = on_alarm;
  sigaction(SIGALRM, &action, nullptr);
}

void throw_if_interrupted() {
  if (g_signal == 0 || getpid() != g_main_pid) return;
  alarm(0);  // unwinding removes the temporary files; main() exits with the status
  throw Interrupted{g_signal};
}

}  // namespace pyro::cli
