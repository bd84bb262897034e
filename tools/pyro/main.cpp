// pyro: the Pyrocumulus command line. The exit status and the form of every message are one
// table for all commands (tools/pyro/command_line.h, docs/cli.md).
#include <CLI/CLI.hpp>

#include "tools/pyro/app.h"
#include "tools/pyro/command_line.h"
#include "tools/pyro/interrupt.h"

int main(int argc, char** argv) {
  CLI::App app{"Pyrocumulus: real-time gaseous phenomena (clouds, fog, mist) splatted as "
               "Gaussian particles"};
  pyro::cli::add_pyro_commands(app);
  pyro::cli::install_interrupt_handlers();
  return pyro::cli::run_command_line(app, argc, argv);
}
