#include "systems/flipbook_fire/flipbook_bake.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/io/scene_loader.h"
#include "engine/io/staging_folder.h"
#include "engine/io/text_file.h"
#include "systems/scene_runtime/scene_runtime.h"

namespace pyro {

FlipbookBakeResult bake_flipbook(const SceneDescription& scene, const FlipbookBakeOptions& options,
                                 const std::string& out) {
  namespace fs = std::filesystem;
  if (!scene.fires.empty())
    throw UserError(scene.file, "/fires",
                    "expected a scene of simulated fire to bake, found flipbook fires (a bake "
                    "renders emitters, not flipbooks)");
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw UserError(out, "--out", "expected a folder for the flipbook frames, found a file");
  const auto t0 = std::chrono::steady_clock::now();
  RuntimeOptions runtime_options;
  runtime_options.readback = false;
  runtime_options.width_override = options.width;
  runtime_options.height_override = options.height;
  SceneRuntime runtime(scene, runtime_options);
  StagingFolder staging(out);
  FlipbookBakeResult result;
  for (int f = 0; f < options.frames; ++f) {
    runtime.step();
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d", f);
    for (const std::string& path : runtime.write_png((staging.path() / name).string()))
      result.files.push_back((fs::path(out) / fs::path(path).filename()).string());
  }
  const nlohmann::json manifest = {{"frames", options.frames},
                                   {"width", options.width},
                                   {"height", options.height},
                                   {"frames_per_second", scene.frames_per_second},
                                   {"source", scene.file}};
  write_text_file((staging.path() / "flipbook.json").string(), manifest.dump(2) + "\n");
  result.files.push_back((fs::path(out) / "flipbook.json").string());
  staging.commit();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

std::string default_flipbook_folder() {
  if (const char* env = std::getenv("PYRO_FLIPBOOK_DIR"); env && *env) return env;
  return PYRO_DEFAULT_FLIPBOOK_DIR;
}

std::string ensure_default_flipbook() {
  const std::string folder = default_flipbook_folder();
  std::error_code ec;
  if (std::filesystem::is_regular_file(std::filesystem::path(folder) / "flipbook.json", ec))
    return folder;
  const std::string scene = content_path("scenes/flipbook_fire.json");
  std::fprintf(stderr, "pyro: baking the default flame flipbook from %s into %s (first run)\n",
               scene.c_str(), folder.c_str());
  bake_flipbook(load_scene(scene), FlipbookBakeOptions{}, folder);
  return folder;
}

}  // namespace pyro
