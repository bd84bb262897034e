// pyro analyze footprint --size N --intervals K [--rule R] [--json] (tools/analyze/closed_forms.h)
// and the registration of the other analyses: projection-error (command_analyze_alignment.cpp)
// stereo (command_analyze_stereo.cpp), blackbody and phase (command_analyze_media.cpp).
#include <memory>

#include "tools/analyze/closed_forms.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

void add_analyze_commands(CLI::App& app) {
  CLI::App* analyze = app.add_subcommand("analyze", "Accuracy analyses against closed forms");
  analyze->require_subcommand(1);
  struct FootprintArgs {
    FootprintAnalysisOptions options;
    bool json = false;
  };
  auto fp = std::make_shared<FootprintArgs>();
  CLI::App* cmd = analyze->add_subcommand(
      "footprint", "The footprint table (Johnson & McAllister eq. 4) against its erf closed form");
  cmd->add_option("--size", fp->options.size, "Table size (size x size nodes)")->check(CLI::Range(2, 4096));
  cmd->add_option("--intervals", fp->options.intervals, "Quadrature intervals along z")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--rule", fp->options.rule, "Composite rule: trapezoid, simpson or midpoint");
  cmd->add_flag("--json", fp->json, "Print one JSON object");
  cmd->callback([fp] { write_result(analyze_footprint(fp->options), fp->json); });
  add_billboard_mode_analysis(*analyze);
  add_analyze_projection_error_command(*analyze);
  add_analyze_stereo_command(*analyze);
  add_analyze_media_commands(*analyze);
  add_flipbook_commands(app, *analyze);  // also `pyro bake-flipbook`
}

}  // namespace pyro::cli
