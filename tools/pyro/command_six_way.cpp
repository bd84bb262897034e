// pyro analyze six-way [--scene SCENE] [--frame F] [--width W] [--height H] [--image PNG] [--json]
// pyro analyze six-way-relight DIR --image PNG [--frame F] [--light X Y Z]
// Six-way lightmaps (tools/bake, baked by pyro bake-flipbook --six-way) relit and measured against
// the CPU reference for the 8 lights between the axes (tools/analyze/six_way_analysis.h).
#include <memory>

#include "tools/analyze/six_way_analysis.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct SixWayAnalysisArgs {
  SixWayAnalysisOptions options;
  bool json = false;
};

}  // namespace

void add_six_way_analysis(CLI::App& analyze) {
  auto relight = std::make_shared<SixWayRelightOptions>();
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
  r->callback([relight] { write_stdout(relight_six_way_bake(*relight)); });

  auto args = std::make_shared<SixWayAnalysisArgs>();
  CLI::App* c = analyze.add_subcommand(
      "six-way",
      "Six-way lightmaps relit for the 8 lights between the axes, against the CPU reference");
  c->add_option("--scene", args->options.scene,
                "Lit smoke scene (default content/scenes/six_way_smoke.json)");
  c->add_option("--frame", args->options.error.frame, "Frame of the simulation to bake")
      ->check(CLI::Range(0, 100000));
  c->add_option("--width", args->options.error.width, "Frame width in pixels")
      ->check(CLI::Range(1, 1024));
  c->add_option("--height", args->options.error.height, "Frame height in pixels")
      ->check(CLI::Range(1, 1024));
  c->add_option("--image", args->options.image,
                "Write a PNG: the reference and the relit bake side by side, for two lights");
  c->add_flag("--json", args->json, "Print one JSON object");
  c->callback([args] { write_result(analyze_six_way(args->options), args->json); });
}

}  // namespace pyro::cli
