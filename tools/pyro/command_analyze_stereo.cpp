// pyro analyze stereo [--interocular I] [--zero-parallax Z0] [--width W] [--height H] [--fov DEG]
//                     [--near N] [--far F] [--eye X Y Z] [--target X Y Z] [--samples K] [--json]
//
// The parallax of the stereo eye frames over the whole view volume
// (tools/analyze/stereo_analysis.h).
#include <memory>

#include "tools/analyze/stereo_analysis.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct StereoArgs {
  StereoAnalysisOptions options;
  bool json = false;
};

}  // namespace

void add_analyze_stereo_command(CLI::App& analyze) {
  auto a = std::make_shared<StereoArgs>();
  CLI::App* cmd = analyze.add_subcommand(
      "stereo",
      "Vertical and horizontal parallax of the stereo eye frames over the whole view volume");
  cmd->add_option("--interocular", a->options.interocular, "Interocular distance I (default 0.065)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--zero-parallax", a->options.zero_parallax, "Zero-parallax distance Z0 (default 5)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--width", a->options.width, "Image width in pixels (default 1024)")
      ->check(CLI::Range(1, 65536));
  cmd->add_option("--height", a->options.height, "Image height in pixels (default 768)")
      ->check(CLI::Range(1, 65536));
  cmd->add_option("--fov", a->options.fov_y_deg, "Vertical field of view, degrees (default 45)")
      ->check(CLI::Range(0.001f, 179.0f));
  cmd->add_option("--near", a->options.near, "Near plane distance (default 0.1)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--far", a->options.far, "Far plane distance (default 200)")->check(CLI::PositiveNumber);
  cmd->add_option("--eye", a->options.eye, "Mono eye position X Y Z (default 0 1.5 8)")->expected(3);
  cmd->add_option("--target", a->options.target, "Point looked at X Y Z (default 0 1.5 0)")->expected(3);
  cmd->add_option("--samples", a->options.samples, "Grid points per axis (default 21)")
      ->check(CLI::Range(2, 401));
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->callback([a] { write_result(analyze_stereo(a->options), a->json); });
}

}  // namespace pyro::cli
