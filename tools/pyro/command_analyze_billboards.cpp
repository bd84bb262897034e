// pyro analyze billboard-modes SCENE [--width W] [--height H] [--frames N] [--json]
// The image difference between billboards facing the viewplane and facing the viewpoint
// (Johnson & McAllister 2005, section 3), per eye of a stereo pair, as RMSE of linear RGB,
// beside the time each mode takes per frame (tools/analyze/billboard_modes.h).
#include <memory>

#include "tools/analyze/billboard_modes.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct Args {
  BillboardModesOptions options;
  bool json = false;
};

}  // namespace

void add_billboard_mode_analysis(CLI::App& analyze) {
  auto a = std::make_shared<Args>();
  CLI::App* cmd = analyze.add_subcommand(
      "billboard-modes", "Image difference (RMSE per eye) and time: viewplane vs viewpoint billboards");
  cmd->add_option("scene", a->options.scene, "Scene file (JSON)")->required();
  cmd->add_option("--width", a->options.width, "Width per eye (default: the scene's)")->check(CLI::Range(1, 8192));
  cmd->add_option("--height", a->options.height, "Height (default: the scene's)")->check(CLI::Range(1, 8192));
  cmd->add_option("--frames", a->options.frames, "Timed frames per mode")->check(CLI::Range(1, 10000));
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->callback([a] {
    a->options.progress = terminal_progress();
    write_result(analyze_billboard_modes(a->options), a->json);
  });
}

}  // namespace pyro::cli
