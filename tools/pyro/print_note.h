#pragma once
// The runtime's notes (systems/runtime/scene_runtime/runtime_options.h: NoteSink) on stderr, one line
// each after the program's name.
#include <cstdio>
#include <string>

namespace pyro::cli {

inline void print_note(const std::string& note) { std::fprintf(stderr, "pyro: %s\n", note.c_str()); }

}  // namespace pyro::cli
