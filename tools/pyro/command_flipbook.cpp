// pyro bake-flipbook SCENE --out DIR [--frames N] [--width W] [--height H] [--loop-blend K]
//                    [--atlas CxR | --six-way] [--json]
// pyro analyze flipbook-pattern [--scene SCENE] [--frames N] [--json]
// Flipbook fire (Rose 2007, chapter 4): baking a flame flipbook from the engine's own
// fire simulation (the scene opened as every command opens it: a quality target's pick applied),
// and measuring how much a frame pattern marches or circles
// (systems/flipbook_fire/flipbook_pattern.h).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/same_file.h"
#include "engine/core/user_error.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/flipbook_bake.h"
#include "systems/flipbook_fire/flipbook_atlas.h"
#include "systems/flipbook_fire/flipbook_layout.h"
#include "systems/flipbook_fire/flipbook_pattern.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/six_way_bake_command.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct BakeArgs {
  std::string scene;
  std::string out;
  FlipbookBakeOptions options;
  bool six_way = false;
  std::string atlas;  // "CxR", empty: a folder of frames
  bool json = false;
};

// The bake replaces --out as a whole: it may not hold (or be) the scene it reads.
void check_bake_destination(const BakeArgs& a) {
  std::filesystem::path folder = std::filesystem::path(a.scene).parent_path();
  if (folder.empty()) folder = ".";
  for (std::filesystem::path at = std::filesystem::absolute(folder).lexically_normal(); !at.empty();
       at = at.parent_path()) {
    if (same_file(at.string(), a.out))
      throw UserError(a.out, "--out", "a folder that does not hold the scene file \"" + a.scene +
                                          "\": the bake replaces the folder as a whole");
    if (at == at.parent_path()) break;
  }
}

void run_bake(BakeArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  if (a.six_way && !a.atlas.empty())
    throw UserError("--atlas", "", "either --atlas (a flame flipbook's atlas) or --six-way (six-way "
                                   "lightmap folders), not both");
  if (!a.atlas.empty()) {
    const AtlasLayout grid = parse_atlas_grid(a.atlas, "--atlas");
    a.options.atlas_columns = grid.columns;
    a.options.atlas_rows = grid.rows;
    a.options.engine_version = PYRO_VERSION;
  }
  const SceneDescription scene = load_scene(a.scene);
  if (a.scene != "-") check_bake_destination(a);
  if (a.six_way) return run_six_way_bake(scene, a.scene, a.out, a.options, a.json);
  check_flipbook_bake(scene, a.options, a.out);
  OpenSceneOptions open;
  open.runtime = flipbook_runtime_options(a.options);
  open.description = scene;
  open.on_note = print_note;
  const OpenedScene opened = open_scene(a.scene, open);  // with the scene's quality pick
  FlipbookBakeResult r = bake_flipbook(*opened.runtime, a.options, a.out);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (r.restored_old_folder)
    print_note("put back " + a.out + ", which a killed bake had moved aside");
  if (r.removed_leftovers > 0)
    print_note("removed " + std::to_string(r.removed_leftovers) + " leftover(s) of killed bakes of " + a.out);
  const nlohmann::json summary = {{"scene", scene.file}, {"out", a.out},
                                  {"frames", a.options.frames}, {"width", a.options.width},
                                  {"height", a.options.height}, {"loop_blend", a.options.loop_blend},
                                  {"atlas", a.atlas},
                                  {"files", r.files},
                                  {"seconds", r.seconds}};
  if (a.json)
    write_stdout(summary.dump() + "\n");
  else
    std::printf("baked %d flame frame(s) %dx%d from %s into %s in %.2f s\n", a.options.frames,
                a.options.width, a.options.height, scene.file.c_str(), a.out.c_str(), r.seconds);
}

struct PatternArgs {
  std::string scene;
  int frames = 32;
  bool json = false;
};

nlohmann::json motion_json(const std::string& name, const FlipbookFire& fire, int frames) {
  const PatternMotion m = measure_pattern_motion(expand_flipbook_groups(fire), frames);
  nlohmann::json groups = nlohmann::json::array();
  for (const FlipbookGroup& g : fire.groups)
    groups.push_back({{"rows", g.rows}, {"columns", g.columns}, {"start_frames", g.start_frames},
                      {"row_start_step", g.row_start_step}, {"increments", g.increments}});
  return {{"name", name},
          {"groups", groups},
          {"march", m.march},
          {"circulation", m.circulation},
          {"transfers", m.transfers},
          {"march_direction", {m.march_direction.x, m.march_direction.y}}};
}

void run_pattern(const PatternArgs& a) {
  nlohmann::json patterns = nlohmann::json::array();
  if (a.scene.empty()) {
    // The thesis' three overlapped pairs (section 4.4) with its three increment patterns, and
    // its triplets (section 4.5: l = -2, m = 1, n = -2).
    const std::vector<std::pair<std::string, std::vector<int>>> pairs = {
        {"pairs +1 +1 (moves away, thesis)", {1, 1}},
        {"pairs +1 -1 (circles, thesis)", {1, -1}},
        {"pairs m=1 n=-2 (thesis' choice)", {1, -2}}};
    for (const auto& [name, increments] : pairs) {
      FlipbookFire fire;
      fire.groups.emplace_back().increments = increments;
      patterns.push_back(motion_json(name, fire, a.frames));
    }
    FlipbookFire triplets;
    FlipbookGroup& g = triplets.groups.emplace_back();
    g.columns = 3;
    g.column_depths = {0.0f, -0.1f, 0.0f};
    g.start_frames = {2, 10, 18};
    g.increments = {-2, 1, -2};
    patterns.push_back(motion_json("triplets l=-2 m=1 n=-2 (thesis' additive scaling)", triplets, a.frames));
    g.increments = {1, 1, 1};
    patterns.push_back(motion_json("triplets +1 +1 +1", triplets, a.frames));
  } else {
    const SceneDescription scene = load_scene(a.scene);
    for (size_t i = 0; i < scene.fires.size(); ++i)
      patterns.push_back(motion_json(scene.fires[i].name.empty() ? "/fires/" + std::to_string(i)
                                                                 : scene.fires[i].name,
                                     scene.fires[i], a.frames));
  }
  const nlohmann::json out = {{"frames", a.frames}, {"patterns", patterns}};
  if (a.json) {
    write_stdout(out.dump() + "\n");
    return;
  }
  std::printf("apparent motion of flipbook frame patterns over a loop of %d frames\n", a.frames);
  std::printf("(transfers of a frame to a neighbouring billboard one step later, per billboard per step)\n");
  std::printf("%-52s %8s %12s %10s\n", "pattern", "march", "circulation", "transfers");
  for (const nlohmann::json& p : patterns)
    std::printf("%-52s %8.4f %12.4f %10.4f\n", p["name"].get<std::string>().c_str(),
                p["march"].get<double>(), p["circulation"].get<double>(), p["transfers"].get<double>());
}

}  // namespace

void add_flipbook_commands(CLI::App& app, CLI::App& analyze) {
  auto bake = std::make_shared<BakeArgs>();
  CLI::App* b = app.add_subcommand(
      "bake-flipbook", "Render a flame flipbook (PNG frames + flipbook.json) from a fire scene");
  b->add_option("scene", bake->scene, "Scene of simulated fire, e.g. content/scenes/flipbook_fire.json")
      ->required();
  b->add_option("--out", bake->out, "Folder for frame_0000.png, ... and flipbook.json")->required();
  b->add_option("--frames", bake->options.frames, "Number of frames")->check(CLI::Range(1, 10000));
  b->add_option("--width", bake->options.width, "Frame width in pixels")->check(CLI::Range(1, 4096));
  b->add_option("--height", bake->options.height, "Frame height in pixels")->check(CLI::Range(1, 4096));
  b->add_option("--loop-blend", bake->options.loop_blend,
                 "Frames cross-faded over the loop's wrap (0: none; below --frames)")
      ->check(CLI::Range(0, 10000));
  b->add_flag("--six-way", bake->six_way,
              "Six-way lightmaps of a lit smoke scene instead (six_way_a/, six_way_b/, six_way.json)");
  b->add_option("--atlas", bake->atlas,
                "Write one atlas of COLUMNSxROWS tiles (e.g. 8x8; row-major from the top left) with "
                "motion vectors and atlas.json instead of a folder of frames");
  b->add_flag("--json", bake->json, "Print a JSON summary as the last line");
  b->callback([bake] { run_bake(*bake); });

  auto pattern = std::make_shared<PatternArgs>();
  CLI::App* p = analyze.add_subcommand(
      "flipbook-pattern", "How much flipbook frame patterns march or circle (Rose 2007, 4.4)");
  p->add_option("--scene", pattern->scene, "Analyse this scene's fires instead of the thesis' patterns");
  p->add_option("--frames", pattern->frames, "Frames in the flipbook loop")->check(CLI::Range(1, 100000));
  p->add_flag("--json", pattern->json, "Print one JSON object");
  p->callback([pattern] { run_pattern(*pattern); });
  add_six_way_analysis(analyze);
}

}  // namespace pyro::cli
