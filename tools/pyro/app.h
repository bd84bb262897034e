#pragma once
// The `pyro` command line as a CLI11 app: main() parses with it, and so do the command-line
// fuzzer and the tests (tests/fuzz/fuzz_targets.cpp), with the subcommands' callbacks removed.
#include <string>

#include <CLI/CLI.hpp>

namespace pyro::cli {

// Registers every subcommand (render, analyze, bench, import-vdb, view, ...) and --version on
// `app`.
void add_pyro_commands(CLI::App& app);

// "pyro 0.1.0" and a line naming the headless OpenGL context's version and renderer, or saying
// that none could be made (the version is printed either way; `pyro --version` exits 0).
std::string version_text();

// Thrown by an app prepared with stop_after_parsing() once every argument has been parsed and
// checked, before any subcommand runs.
struct ParsedOnly {};

// Makes app.parse() check the arguments (values, ranges, requirements) and then throw ParsedOnly
// instead of running the chosen subcommand: nothing is rendered or written. (The subcommands'
// callbacks own the variables their options write to, so they are stopped, not removed.)
void stop_after_parsing(CLI::App& app);

}  // namespace pyro::cli
