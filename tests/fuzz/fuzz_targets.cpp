#include "tests/fuzz/fuzz_targets.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "engine/core/user_error.h"
#include "engine/io/isolated_call.h"
#include "engine/io/particle_file.h"
#include "engine/io/png_file.h"
#include "systems/runtime/scene/scene_loader.h"
#include "engine/io/vdb_file_check.h"
#include "engine/io/vdb_reader.h"
#include "tools/pyro/app.h"

namespace pyro::fuzz {

namespace {

// A file holding the input, named for this process, removed when done.
class TempFile {
 public:
  TempFile(const uint8_t* data, std::size_t size, const char* extension)
      : path_((std::filesystem::temp_directory_path() /
               ("pyro_fuzz_" + std::to_string(::getpid()) + extension))
                  .string()) {
    std::FILE* f = std::fopen(path_.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write " + path_);
    if (size > 0) std::fwrite(data, 1, size, f);
    std::fclose(f);
  }
  ~TempFile() { std::remove(path_.c_str()); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace

void scene(const uint8_t* data, std::size_t size) {
  try {
    parse_scene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const UserError&) {
  }
}

void vdb(const uint8_t* data, std::size_t size) {
  // OpenVDB runs in a child process (engine/io/isolated_call.h); a damaged input that makes it
  // loop is given up after 10 s, inside libFuzzer's 30 s timeout.
  vdb_isolation_limits().timeout_seconds = 10.0;
  const TempFile file(data, size, ".vdb");
  try {
    check_vdb_file_structure(file.path());
    const std::vector<VdbGridInfo> grids = list_vdb_grids(file.path());
    if (!grids.empty()) read_vdb_grid(file.path());
  } catch (const UserError&) {
  }
}

void png(const uint8_t* data, std::size_t size) {
  const TempFile file(data, size, ".png");
  try {
    read_png(file.path());
  } catch (const UserError&) {
  }
}

void particles(const uint8_t* data, std::size_t size) {
  const TempFile file(data, size, ".pyrop");
  ParticleFile read;
  try {
    read = read_particle_file(file.path());
  } catch (const UserError&) {
    return;
  }
  const std::string again = file.path() + ".again.pyrop";
  write_particle_file(again, read);  // throws (escapes: a bug) for what the reader accepted
  std::ifstream in(again, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::remove(again.c_str());
  if (bytes != std::string(reinterpret_cast<const char*>(data), size)) {
    std::fprintf(stderr, "fuzz particles: an accepted file of %zu bytes is written back as %zu "
                         "other bytes\n", size, bytes.size());
    std::abort();
  }
}

void cli(const uint8_t* data, std::size_t size) {
  std::vector<std::string> args{"pyro"};
  std::string current;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n') {
      args.push_back(current);
      current.clear();
    } else {
      current.push_back(static_cast<char>(data[i]));
    }
  }
  if (!current.empty()) args.push_back(current);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  CLI::App app{"pyro (fuzzed)"};
  cli::add_pyro_commands(app);
  cli::stop_after_parsing(app);
  try {
    app.parse(static_cast<int>(args.size()), argv.data());
  } catch (const cli::ParsedOnly&) {
  } catch (const CLI::ParseError&) {
  } catch (const UserError&) {
  }
}

bool run(const std::string& name, const std::string& input) {
  const auto* data = reinterpret_cast<const uint8_t*>(input.data());
  if (name == "scene") scene(data, input.size());
  else if (name == "vdb") vdb(data, input.size());
  else if (name == "png") png(data, input.size());
  else if (name == "particles") particles(data, input.size());
  else if (name == "cli") cli(data, input.size());
  else return false;
  return true;
}

}  // namespace pyro::fuzz
