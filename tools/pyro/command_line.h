#pragma once
// How `pyro` ends: one exit status for every command (docs/cli.md, "Exit status"), and one
// message on stderr that starts with "pyro: error:".
//
//   0    success
//   1    the environment or an I/O failure: a full disk, a read-only file system, a failed
//        write to standard output, a missing helper program, an internal error
//   2    the user's input: a scene, VDB or particle file, an argument, an unknown command or
//        option (with "did you mean")
//   3    no usable OpenGL context
//   130  interrupted by SIGINT; 143 by SIGTERM (tools/pyro/interrupt.h)
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

namespace pyro::cli {

// Parses `argv` with `app` (add_pyro_commands), runs the chosen command and returns the exit
// status, having printed the error, if any, and flushed standard output (a failed flush is 1).
int run_command_line(CLI::App& app, int argc, char** argv);

}  // namespace pyro::cli
