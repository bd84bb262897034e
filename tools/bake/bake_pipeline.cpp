#include "tools/bake/bake_pipeline.h"

#include <chrono>
#include <filesystem>

#include "engine/core/format_text.h"
#include "engine/core/user_error.h"
#include "engine/io/output_gate.h"
#include "systems/flipbook_fire/flipbook_atlas.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_inputs.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/bake/six_way_bake.h"

namespace pyro {

namespace {

// The bake replaces --out as a whole (the gate: engine/io/output_gate.h), and what it holds in
// memory and writes must fit: the frames simulated (with their motion for an atlas) and the
// atlas images, whose sides the engine's readers limit.
void check_bake_destination(const BakeOptions& a, const SceneDescription& scene) {
  OutputGate()
      .reads(scene_inputs(a.scene, scene))
      .writes({a.out, "--out", OutputShape::folder, flipbook_bake_output_kind(), a.flipbook.overwrite})
      .check();
  const FlipbookBakeOptions& o = a.flipbook;
  const int64_t frame_pixels = int64_t(o.width) * o.height;
  const int64_t simulated = int64_t(o.frames) + o.loop_blend;
  if (a.kind != BakeKind::atlas) {
    check_memory_need("--frames", "the simulated frames", simulated * frame_pixels * 4);
    return;
  }
  check_image_size("--atlas", "an atlas", int64_t(o.atlas_columns) * o.width, int64_t(o.atlas_rows) * o.height);
  // Per frame pixel: the frame (4 bytes) and its motion sums (3 floats); per atlas pixel: the
  // colour and motion PNGs (3 + 4 bytes) and EXRs (2 x 4 halves), and their packing.
  const int64_t atlas_pixels = int64_t(o.atlas_columns) * o.atlas_rows * frame_pixels;
  check_memory_need("--atlas", "the atlas and its simulated frames", simulated * frame_pixels * 16 + atlas_pixels * 40);
}

SixWayBakeOptions six_way_options(const FlipbookBakeOptions& flipbook) {
  SixWayBakeOptions options;
  options.frames = flipbook.frames;
  options.width = flipbook.width;
  options.height = flipbook.height;
  options.loop_blend = flipbook.loop_blend;
  options.overwrite = flipbook.overwrite;
  return options;
}

// The kind's refusals (check_six_way_bake or check_flipbook_bake), then how it runs the scene.
RuntimeOptions check_kind(const SceneDescription& scene, const BakeOptions& a) {
  if (a.kind == BakeKind::six_way) {
    check_six_way_bake(scene, six_way_options(a.flipbook), a.out);
    return six_way_runtime_options(six_way_options(a.flipbook));
  }
  check_flipbook_bake(scene, a.flipbook, a.out);
  return flipbook_runtime_options(a.flipbook);
}

// The bake of the kind on the opened runtime, as a flipbook bake's result.
FlipbookBakeResult bake_kind_from(SceneRuntime& runtime, const BakeOptions& a) {
  if (a.kind != BakeKind::six_way) return bake_flipbook(runtime, a.flipbook, a.out);
  const SixWayBakeResult r = bake_six_way(runtime, six_way_options(a.flipbook), a.out);
  FlipbookBakeResult result;
  result.files = r.files;
  result.removed_leftovers = r.removed_leftovers;
  result.restored_old_folder = r.restored_old_folder;
  return result;
}

BakeReport bake_report(const BakeOptions& a, const std::string& scene_file,
                       const FlipbookBakeResult& r) {
  const FlipbookBakeOptions& o = a.flipbook;
  BakeReport report;
  report.json = {{"scene", scene_file}, {"out", a.out}};
  if (a.kind == BakeKind::six_way) report.json["six_way"] = true;
  report.json.update({{"frames", o.frames},
                      {"width", o.width},
                      {"height", o.height},
                      {"loop_blend", o.loop_blend}});
  if (a.kind != BakeKind::six_way) report.json["atlas"] = a.atlas;
  report.json.update({{"files", r.files}, {"seconds", r.seconds}});
  if (a.kind == BakeKind::six_way)
    report.text = format_text(
        "baked %d six-way frame(s) %dx%d (two textures each) from %s into %s in %.2f s\n", o.frames,
        o.width, o.height, scene_file.c_str(), a.out.c_str(), r.seconds);
  else
    report.text = format_text("baked %d flame frame(s) %dx%d from %s into %s in %.2f s\n", o.frames,
                              o.width, o.height, scene_file.c_str(), a.out.c_str(), r.seconds);
  return report;
}

}  // namespace

BakeKind bake_kind(bool six_way, const std::string& atlas) {
  if (six_way && !atlas.empty())
    throw UserError("--atlas", "",
                    "either --atlas (a flame flipbook's atlas) or --six-way (six-way "
                    "lightmap folders), not both");
  if (six_way) return BakeKind::six_way;
  return atlas.empty() ? BakeKind::frames : BakeKind::atlas;
}

BakeReport run_bake(BakeOptions a, const NoteSink& on_note) {
  const auto t0 = std::chrono::steady_clock::now();
  if (a.kind == BakeKind::atlas) {
    const AtlasLayout grid = parse_atlas_grid(a.atlas, "--atlas");
    a.flipbook.atlas_columns = grid.columns;
    a.flipbook.atlas_rows = grid.rows;
    a.flipbook.engine_version = PYRO_VERSION;
  }
  const SceneDescription scene = load_scene(a.scene);
  OpenSceneOptions open;
  open.runtime = check_kind(scene, a);
  check_bake_destination(a, scene);
  open.description = scene;
  open.on_note = on_note;
  const OpenedScene opened = open_scene(a.scene, open);  // with the scene's quality pick
  FlipbookBakeResult r = bake_kind_from(*opened.runtime, a);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (r.restored_old_folder && on_note)
    on_note("put back " + a.out + ", which a killed bake had moved aside");
  if (r.removed_leftovers > 0 && on_note)
    on_note("removed " + std::to_string(r.removed_leftovers) + " leftover(s) of killed bakes of " +
            a.out);
  return bake_report(a, scene.file, r);
}

}  // namespace pyro
