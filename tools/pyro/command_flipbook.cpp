// pyro bake-flipbook SCENE --out DIR [--frames N] [--width W] [--height H] [--loop-blend K]
//                    [--atlas CxR | --six-way] [--json]
// pyro analyze flipbook-pattern [--scene SCENE] [--frames N] [--json]
// Flipbook fire (Rose 2007, chapter 4): a flame flipbook, its atlas or six-way lightmaps baked
// by one pipeline (tools/bake/bake_pipeline.h), and how much a frame pattern marches or circles
// (tools/analyze/flipbook_pattern_analysis.h).
#include <memory>
#include <string>

#include "tools/analyze/flipbook_pattern_analysis.h"
#include "tools/bake/bake_pipeline.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct BakeArgs {
  BakeOptions options;
  bool six_way = false;
  bool json = false;
};

struct PatternArgs {
  FlipbookPatternOptions options;
  bool json = false;
};

}  // namespace

void add_flipbook_commands(CLI::App& app, CLI::App& analyze) {
  auto bake = std::make_shared<BakeArgs>();
  CLI::App* b = app.add_subcommand(
      "bake-flipbook", "Render a flame flipbook (PNG frames + flipbook.json) from a fire scene");
  b->add_option("scene", bake->options.scene, "Scene of simulated fire, e.g. content/scenes/flipbook_fire.json")
      ->required();
  b->add_option("--out", bake->options.out, "Folder for frame_0000.png, ... and flipbook.json")->required();
  b->add_option("--frames", bake->options.flipbook.frames, "Number of frames")->check(CLI::Range(1, 10000));
  b->add_option("--width", bake->options.flipbook.width, "Frame width in pixels")->check(CLI::Range(1, 4096));
  b->add_option("--height", bake->options.flipbook.height, "Frame height in pixels")->check(CLI::Range(1, 4096));
  b->add_option("--loop-blend", bake->options.flipbook.loop_blend,
                 "Frames cross-faded over the loop's wrap (0: none; below --frames)")
      ->check(CLI::Range(0, 10000));
  b->add_flag("--six-way", bake->six_way,
              "Six-way lightmaps of a lit smoke scene instead (six_way_a/, six_way_b/, six_way.json)");
  b->add_option("--atlas", bake->options.atlas,
                "Write one atlas of COLUMNSxROWS tiles (e.g. 8x8; row-major from the top left) with "
                "motion vectors and atlas.json instead of a folder of frames");
  b->add_flag("--overwrite", bake->options.flipbook.overwrite,
              "Replace --out even when it holds files no bake wrote (they are kept)");
  b->add_flag("--json", bake->json, "Print a JSON summary as the last line");
  b->callback([bake] {
    bake->options.kind = bake_kind(bake->six_way, bake->options.atlas);
    write_result(run_bake(bake->options, print_note), bake->json);
  });

  auto pattern = std::make_shared<PatternArgs>();
  CLI::App* p = analyze.add_subcommand(
      "flipbook-pattern", "How much flipbook frame patterns march or circle (Rose 2007, 4.4)");
  p->add_option("--scene", pattern->options.scene, "Analyse this scene's fires instead of the thesis' patterns");
  p->add_option("--frames", pattern->options.frames, "Frames in the flipbook loop")->check(CLI::Range(1, 100000));
  p->add_flag("--json", pattern->json, "Print one JSON object");
  p->callback([pattern] { write_result(analyze_flipbook_pattern(pattern->options), pattern->json); });
  add_six_way_analysis(analyze);
}

}  // namespace pyro::cli
