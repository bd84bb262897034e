#pragma once
// SIGINT (Ctrl-C) and SIGTERM end a command cleanly: the handler only records the signal, and the
// next progress step (tools/pyro/progress.h) throws Interrupted, so that every staging folder and
// temporary file is removed as the stack unwinds and main() exits with 128 + the signal (130,
// 143). Work that reports no progress for 3 s, or a second signal, ends the process at once with
// the same status; what it leaves is removed by the next run into the same place.
namespace pyro::cli {

struct Interrupted {
  int signal = 0;
};

// Installs the handlers (once, in main).
void install_interrupt_handlers();

// Throws Interrupted when a signal arrived (in the main process only: a forked helper is left
// to its parent).
void throw_if_interrupted();

}  // namespace pyro::cli
