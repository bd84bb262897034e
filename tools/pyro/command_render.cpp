// pyro render SCENE --out DIR [--width W] [--height H] [--frames N] [--json]
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "components/draw_list.h"
#include "engine/core/user_error.h"
#include "engine/io/scene_loader.h"
#include "systems/scene_runtime/scene_runtime.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/render_options.h"

namespace pyro::cli {

namespace {

struct RenderArgs {
  std::string scene;
  std::string out;
  int width = 0, height = 0;
  int frames = 1;
  bool json = false;
  RuntimeOptions runtime;
};

std::string frame_name(int f) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d", f);
  return name;
}

void run_render(const RenderArgs& a) {
  // Everything the user can get wrong is checked before anything is written.
  const SceneDescription scene = load_scene(a.scene);
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a.out, ec) && !fs::is_directory(a.out, ec))
    throw UserError(a.out, "--out", "expected a folder for the frames, found a file");

  const auto t0 = std::chrono::steady_clock::now();
  RuntimeOptions options = a.runtime;
  options.readback = false;
  options.width_override = a.width;
  options.height_override = a.height;
  SceneRuntime runtime(scene, options);
  fs::create_directories(a.out, ec);
  if (ec) throw UserError(a.out, "--out", "cannot create the output folder: " + ec.message());

  nlohmann::json files = nlohmann::json::array();
  Progress progress("render " + scene.name, static_cast<size_t>(a.frames));
  for (int f = 0; f < a.frames; ++f) {
    runtime.step();
    for (const std::string& path : runtime.write_png((fs::path(a.out) / frame_name(f)).string()))
      files.push_back(path);
    progress.update(static_cast<size_t>(f + 1));
  }
  progress.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const auto* lists = runtime.world().try_resource<EyeDrawLists>();
  const size_t particles = lists && !lists->eyes.empty() ? lists->eyes[0].size() : 0;
  const RenderSettings& rs = runtime.settings();
  std::string stereo;
  for (const auto& [name, mode] : stereo_mode_names())
    if (mode == rs.stereo_mode) stereo = name;
  nlohmann::json systems = nlohmann::json::array();
  for (const auto& s : runtime.schedule().stats())
    systems.push_back({{"name", s.name}, {"phase", ecs::phase_name(s.phase)}, {"mean_ms", s.mean_ms()}});
  nlohmann::json summary = {
      {"scene", scene.file},
      {"name", scene.name},
      {"out", a.out},
      {"frames", a.frames},
      {"width", rs.width},
      {"height", rs.height},
      {"stereo", stereo},
      {"billboards", rs.alignment == BillboardAlignment::viewplane ? "viewplane" : "viewpoint"},
      {"layer_scale", rs.layer_scale},
      {"particles", particles},
      {"files", files},
      {"seconds", seconds},
      {"ms_per_frame", seconds * 1000.0 / a.frames},
      {"systems", systems},
      {"renderer", shared_headless_context().description()}};
  if (a.json) {
    std::printf("%s\n", summary.dump().c_str());
  } else {
    std::printf("rendered %d frame(s) of %s (%dx%d %s, %zu particles) into %s in %.2f s\n",
                a.frames, scene.file.c_str(), rs.width, rs.height, stereo.c_str(), particles,
                a.out.c_str(), seconds);
  }
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file to PNG frames");
  cmd->add_option("scene", args->scene, "Scene file (JSON), e.g. content/scenes/fog.json")->required();
  cmd->add_option("--out", args->out, "Folder for frame_0000.png, frame_0001.png, ...")->required();
  cmd->add_option("--width", args->width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--frames", args->frames, "Number of frames")->check(CLI::Range(1, 1000000));
  cmd->add_flag("--json", args->json, "Print a JSON summary as the last line");
  add_render_options(cmd, args->runtime);
  cmd->callback([args] { run_render(*args); });
}

}  // namespace pyro::cli
