// pyro bake-flipbook SCENE --out DIR --six-way [--frames N] [--width W] [--height H] [--loop-blend
// K] pyro analyze six-way [--scene SCENE] [--frame F] [--width W] [--height H] [--image PNG]
// [--json] pyro analyze six-way-relight DIR --image PNG [--frame F] [--light X Y Z] Six-way
// lightmaps (tools/bake): baked from a lit smoke scene as Unity VFX Graph's two
// textures per frame, and their relighting measured against the CPU reference for the 8 lights
// between the axes.
#include <chrono>
#include <cstdio>
#include <glm/geometric.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/io/png_file.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/bake/six_way_bake.h"
#include "tools/analyze/six_way_error.h"
#include "tools/bake/six_way_folder.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/six_way_bake_command.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

void run_six_way_bake(const SceneDescription& scene, const std::string& scene_file,
                      const std::string& out, const FlipbookBakeOptions& flipbook, bool json) {
  SixWayBakeOptions options;
  options.frames = flipbook.frames;
  options.width = flipbook.width;
  options.height = flipbook.height;
  options.loop_blend = flipbook.loop_blend;
  const auto t0 = std::chrono::steady_clock::now();
  check_six_way_bake(scene, options, out);
  OpenSceneOptions open;
  open.runtime = six_way_runtime_options(options);
  open.description = scene;
  open.on_note = print_note;
  const OpenedScene opened = open_scene(scene_file, open);  // with the scene's quality pick
  SixWayBakeResult r = bake_six_way(*opened.runtime, options, out);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (r.restored_old_folder)
    print_note("put back " + out + ", which a killed bake had moved aside");
  if (r.removed_leftovers > 0)
    print_note("removed " + std::to_string(r.removed_leftovers) +
               " leftover(s) of killed bakes of " + out);
  const nlohmann::json summary = {{"scene", scene.file},
                                  {"out", out},
                                  {"six_way", true},
                                  {"frames", options.frames},
                                  {"width", options.width},
                                  {"height", options.height},
                                  {"loop_blend", options.loop_blend},
                                  {"files", r.files},
                                  {"seconds", r.seconds}};
  if (json)
    write_stdout(summary.dump() + "\n");
  else
    std::printf("baked %d six-way frame(s) %dx%d (two textures each) from %s into %s in %.2f s\n",
                options.frames, options.width, options.height, scene.file.c_str(), out.c_str(),
                r.seconds);
}

namespace {

struct SixWayAnalysisArgs {
  std::string scene;
  std::string image;
  SixWayErrorOptions options;
  bool json = false;
};

std::string vector_text(const glm::vec3& v) {
  char text[64];
  std::snprintf(text, sizeof text, "(%+.3f, %+.3f, %+.3f)", v.x, v.y, v.z);
  return text;
}

void write_picture(const RgbImage& picture, const std::string& path) {
  std::vector<float> rgba(static_cast<size_t>(picture.width) * picture.height * 4, 1.0f);
  for (size_t p = 0; p < rgba.size() / 4; ++p)
    for (int c = 0; c < 3; ++c) rgba[4 * p + c] = picture.rgb[3 * p + c];
  write_png(path, picture.width, picture.height, 3,
            linear_rgba_to_srgb8(rgba, picture.width, picture.height));
}

void run_six_way_analysis(const SixWayAnalysisArgs& a) {
  const std::string file = a.scene.empty() ? content_path("scenes/six_way_smoke.json") : a.scene;
  const SixWayErrorReport r = measure_six_way_error(load_scene(file), a.options);
  if (!a.image.empty()) write_picture(r.picture, a.image);
  nlohmann::json directions = nlohmann::json::array();
  for (const SixWayDirectionError& e : r.directions)
    directions.push_back(
        {{"towards_light", {e.towards_light.x, e.towards_light.y, e.towards_light.z}},
         {"rmse_six_way_engine", e.six_way_engine},
         {"rmse_six_way_reference_faces", e.six_way_reference},
         {"rmse_engine_lit", e.engine_lit},
         {"rmse_six_way_engine_vs_engine_lit", e.six_way_engine_vs_engine_lit}});
  const nlohmann::json out = {{"scene", file},
                              {"frame", a.options.frame},
                              {"width", a.options.width},
                              {"height", a.options.height},
                              {"particles", r.particles},
                              {"directions", directions},
                              {"seconds", r.seconds}};
  if (a.json) {
    write_stdout(out.dump() + "\n");
    return;
  }
  std::printf(
      "six-way relighting of %s, frame %d at %dx%d (%zu particles), RMSE against the CPU "
      "reference\n",
      file.c_str(), a.options.frame, a.options.width, a.options.height, r.particles);
  std::printf("%-26s %14s %16s %12s %22s\n", "towards the light", "six-way (GL)", "six-way (ref.)",
              "GL lit", "six-way (GL) vs GL lit");
  for (const SixWayDirectionError& e : r.directions)
    std::printf("%-26s %14.4f %16.4f %12.4f %22.4f\n", vector_text(e.towards_light).c_str(),
                e.six_way_engine, e.six_way_reference, e.engine_lit,
                e.six_way_engine_vs_engine_lit);
}

struct SixWayRelightArgs {
  std::string folder;
  std::string image;
  int frame = 0;
  std::vector<float> light{1.0f, 1.0f, 1.0f};
};

void run_six_way_relight(const SixWayRelightArgs& a) {
  const glm::vec3 towards(a.light.at(0), a.light.at(1), a.light.at(2));
  if (glm::length(towards) < 1e-6f)
    throw UserError("", "--light", "expected a non-zero direction towards the light, found 0 0 0");
  const SixWayFrame frame = unpack_six_way(read_six_way_frame(a.folder, a.frame));
  write_picture(relight_six_way(frame, towards), a.image);
  std::printf("relit frame %d of %s (%dx%d) for the light towards %s into %s\n", a.frame,
              a.folder.c_str(), frame.width, frame.height,
              vector_text(glm::normalize(towards)).c_str(), a.image.c_str());
}

}  // namespace

void add_six_way_analysis(CLI::App& analyze) {
  auto relight = std::make_shared<SixWayRelightArgs>();
  CLI::App* r = analyze.add_subcommand(
      "six-way-relight",
      "A baked six-way frame relit on the CPU by Unity's blend, over black, as a PNG");
  r->add_option("folder", relight->folder, "Folder of a bake-flipbook --six-way bake")->required();
  r->add_option("--image", relight->image, "The relit frame (PNG)")->required();
  r->add_option("--frame", relight->frame, "Frame of the bake")->check(CLI::Range(0, 100000));
  r->add_option("--light", relight->light,
                "Direction towards the light in the baking camera's frame (x right, "
                "y up, z towards the viewer); default 1 1 1")
      ->expected(3);
  r->callback([relight] { run_six_way_relight(*relight); });

  auto args = std::make_shared<SixWayAnalysisArgs>();
  CLI::App* c = analyze.add_subcommand(
      "six-way",
      "Six-way lightmaps relit for the 8 lights between the axes, against the CPU reference");
  c->add_option("--scene", args->scene,
                "Lit smoke scene (default content/scenes/six_way_smoke.json)");
  c->add_option("--frame", args->options.frame, "Frame of the simulation to bake")
      ->check(CLI::Range(0, 100000));
  c->add_option("--width", args->options.width, "Frame width in pixels")
      ->check(CLI::Range(1, 1024));
  c->add_option("--height", args->options.height, "Frame height in pixels")
      ->check(CLI::Range(1, 1024));
  c->add_option("--image", args->image,
                "Write a PNG: the reference and the relit bake side by side, for two lights");
  c->add_flag("--json", args->json, "Print one JSON object");
  c->callback([args] { run_six_way_analysis(*args); });
}

}  // namespace pyro::cli
