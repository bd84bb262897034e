#include "systems/scene_runtime/flipbook_bake.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/core/content_location.h"
#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "systems/scene/scene_loader.h"
#include "engine/io/png_file.h"
#include "engine/io/folder_replacement.h"
#include "engine/math/color.h"
#include "engine/io/text_file.h"
#include "systems/scene_runtime/scene_runtime.h"

namespace pyro {

void check_flipbook_bake(const SceneDescription& scene, const FlipbookBakeOptions& options,
                         const std::string& out) {
  namespace fs = std::filesystem;
  if (!scene.fires.empty())
    throw UserError(scene.file, "/fires",
                    "expected a scene of simulated fire to bake, found flipbook fires (a bake "
                    "renders emitters, not flipbooks)");
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw UserError(out, "--out", "expected a folder for the flipbook frames, found a file");
  if (options.loop_blend < 0 || options.loop_blend >= options.frames)
    throw UserError("", "--loop-blend",
                    "expected a cross-fade shorter than the flipbook (0 to " +
                        std::to_string(options.frames - 1) + " frames), found " +
                        std::to_string(options.loop_blend));
}

RuntimeOptions flipbook_runtime_options(const FlipbookBakeOptions& options) {
  RuntimeOptions runtime_options;
  runtime_options.readback = false;
  runtime_options.width_override = options.width;
  runtime_options.height_override = options.height;
  return runtime_options;
}

FlipbookBakeResult bake_flipbook(const SceneDescription& scene, const FlipbookBakeOptions& options,
                                 const std::string& out) {
  check_flipbook_bake(scene, options, out);
  const auto t0 = std::chrono::steady_clock::now();
  // Behind the front door: the asset step of a runtime being opened bakes here.
  SceneRuntime runtime(scene, flipbook_runtime_options(options));
  FlipbookBakeResult result = bake_flipbook(runtime, options, out);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

FlipbookBakeResult bake_flipbook(SceneRuntime& runtime, const FlipbookBakeOptions& options,
                                 const std::string& out) {
  namespace fs = std::filesystem;
  const auto t0 = std::chrono::steady_clock::now();
  const SceneDescription& scene = runtime.scene();
  FolderReplacement staging(out);
  std::vector<std::vector<uint8_t>> simulated;  // RGBA8 sRGB, frames + loop_blend of them
  int width = 0, height = 0;
  for (int f = 0; f < options.frames + options.loop_blend; ++f) {
    runtime.step();
    ShownImage image = runtime.read_output();
    width = image.width;
    height = image.height;
    simulated.push_back(std::move(image.rgba));
  }
  FlipbookBakeResult result;
  result.removed_leftovers = staging.removed_leftovers();
  result.restored_old_folder = staging.restored_old_folder();
  const size_t pixels = static_cast<size_t>(width) * height;
  for (int f = 0; f < options.frames; ++f) {
    std::vector<uint8_t> rgb(pixels * 3);
    const std::vector<uint8_t>& a = simulated[static_cast<size_t>(f)];
    if (f < options.loop_blend) {
      // Cross-fade in linear light: w on frame f, 1 - w on frame frames + f.
      const std::vector<uint8_t>& b = simulated[static_cast<size_t>(options.frames + f)];
      const float w = static_cast<float>(f + 1) / static_cast<float>(options.loop_blend + 1);
      for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) {
          const float la = srgb_to_linear(a[i * 4 + c] / 255.0f), lb = srgb_to_linear(b[i * 4 + c] / 255.0f);
          rgb[i * 3 + c] = to_byte(linear_to_srgb(w * la + (1.0f - w) * lb));
        }
    } else {
      for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = a[i * 4 + c];
    }
    apply_frame_fade(options.fade, width, height, rgb);
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", f);
    write_png((staging.path() / name).string(), width, height, 3, rgb);
    result.files.push_back((fs::path(out) / name).string());
  }
  const nlohmann::json manifest = {{"frames", options.frames},
                                   {"width", options.width},
                                   {"height", options.height},
                                   {"frames_per_second", scene.frames_per_second},
                                   {"loop_blend", options.loop_blend},
                                   {"source", scene.file}};
  write_text_file((staging.path() / "flipbook.json").string(), manifest.dump(2) + "\n");
  result.files.push_back((fs::path(out) / "flipbook.json").string());
  staging.commit();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

std::string default_flipbook_folder() {
  if (const char* env = std::getenv("PYRO_FLIPBOOK_DIR"); env && *env) return env;
  return built_in_flipbook_dir();
}

bool default_flipbook_baked() {
  std::error_code ec;
  return std::filesystem::is_regular_file(
      std::filesystem::path(default_flipbook_folder()) / "flipbook.json", ec);
}

std::string ensure_default_flipbook(const NoteSink& on_note) {
  const std::string folder = default_flipbook_folder();
  if (default_flipbook_baked()) return folder;
  const std::string scene = content_path("scenes/flipbook_fire.json");
  if (on_note)
    on_note("baking the default flame flipbook from " + scene + " into " + folder + " (first run)");
  bake_flipbook(load_scene(scene), FlipbookBakeOptions{}, folder);
  return folder;
}

}  // namespace pyro
