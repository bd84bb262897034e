#pragma once
// `pyro render` from the tests, and what an output folder then holds.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tests/support/file_bytes.h"
#include "tests/support/test_paths.h"

namespace pyro::test {

// Every entry of `dir` with its bytes (folders as "<dir>").
inline std::map<std::string, std::string> contents(const std::filesystem::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    m[e.path().filename().string()] = e.is_directory() ? "<dir>" : read_bytes(e.path());
  return m;
}

// The arguments of `pyro render content/scenes/SCENE --out OUT --frames FRAMES` at SIZE x SIZE.
inline std::vector<std::string> render_args(const std::string& scene, const std::filesystem::path& out,
                                            const std::string& frames, int size,
                                            const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"render", scene_path(scene), "--out", out.string(),
                                   "--frames", frames, "--width", std::to_string(size),
                                   "--height", std::to_string(size)};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

inline CommandResult render(const std::string& scene, const std::filesystem::path& out,
                            const std::string& frames, int size,
                            const std::vector<std::string>& extra = {}) {
  return run_pyro(render_args(scene, out, frames, size, extra));
}

}  // namespace pyro::test
