#pragma once
// What each libFuzzer target does with one input. The fuzzers' entry points
// (fuzz_*_main.cpp, built with PYRO_FUZZ=ON) call these; so does the normal test suite, on the
// seed corpus and on every input that once crashed (tests/fuzz/regressions/<target>/).
//
// Each returns normally when the input is handled: accepted, or refused with pyro::UserError
// (or CLI11's parse error for the command line). Anything else escapes: an exception of another
// type, a crash or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

namespace pyro::fuzz {

// pyro::parse_scene on the bytes as scene JSON.
void scene(const uint8_t* data, std::size_t size);
// The bytes written to a temporary .vdb file, then check_vdb_file_structure, list_vdb_grids and
// read_vdb_grid, as `pyro import-vdb` does.
void vdb(const uint8_t* data, std::size_t size);
// The bytes written to a temporary .png file, then read_png.
void png(const uint8_t* data, std::size_t size);
// The bytes written to a temporary .pyrop file, then read_particle_file, as a scene's particle
// volume is loaded. An accepted file must come back byte for byte when written again
// (write_particle_file), or the target aborts.
void particles(const uint8_t* data, std::size_t size);
// The bytes split into arguments at newlines, then parsed by the `pyro` CLI11 app, stopped before any
// command runs (tools/pyro/app.h: stop_after_parsing).
void cli(const uint8_t* data, std::size_t size);

// Runs the target called `name` ("scene", "vdb", "png", "particles", "cli"); false for an
// unknown name.
bool run(const std::string& name, const std::string& input);

}  // namespace pyro::fuzz
