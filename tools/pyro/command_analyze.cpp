// pyro analyze footprint --size N --intervals K [--rule R] [--json]
// and the registration of the other analyses: projection-error (command_analyze_alignment.cpp)
// stereo (command_analyze_stereo.cpp), blackbody and phase (command_analyze_media.cpp).
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/math/footprint.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct FootprintArgs {
  int size = 64;
  int intervals = 100;
  std::string rule = "trapezoid";
  bool json = false;
};

void run_footprint(const FootprintArgs& a) {
  QuadratureRule rule{};
  if (!parse_quadrature_rule(a.rule, rule))
    throw UserError("command line", "--rule", "expected trapezoid, simpson or midpoint, found \"" + a.rule + "\"");
  if (rule == QuadratureRule::simpson && a.intervals % 2 != 0)
    throw UserError("command line", "--intervals", "Simpson's rule needs an even number of intervals, found " +
                                                       std::to_string(a.intervals));
  const FootprintTable table = make_footprint_table(a.size, a.intervals, rule);
  const FootprintError e = measure_footprint_error(table);
  const nlohmann::json out = {
      {"size", a.size},
      {"intervals", a.intervals},
      {"rule", quadrature_rule_name(rule)},
      {"extent", table.extent},
      {"max_abs_error", e.max_abs_error},
      {"max_abs_error_scaled", e.max_abs_error_scaled},
      {"max_abs_error_sampled", e.max_abs_error_sampled},
      {"max_rel_error_raw_sampled", e.max_rel_error_raw_sampled},
      {"sample_grid", e.sample_grid},
      {"max_entry_raw", table.max_raw},
      {"closed_form_peak", footprint_closed_form(0.0, 0.0, table.extent)}};
  if (a.json) {
    write_stdout(out.dump() + "\n");
    return;
  }
  std::printf("footprint table %dx%d, %d %s intervals over [-%g, %g]\n", a.size, a.size,
              a.intervals, quadrature_rule_name(rule), table.extent, table.extent);
  std::printf("  raw integrals vs erf closed form (quadrature error): %.3e\n", e.max_abs_error);
  std::printf("  scaled table vs scaled closed form:                  %.3e\n", e.max_abs_error_scaled);
  std::printf("  bilinear-sampled table vs exp(-r^2/2), %d^2 points: %.3e\n", e.sample_grid,
              e.max_abs_error_sampled);
}

}  // namespace

void add_analyze_commands(CLI::App& app) {
  CLI::App* analyze = app.add_subcommand("analyze", "Accuracy analyses against closed forms");
  analyze->require_subcommand(1);
  auto fp = std::make_shared<FootprintArgs>();
  CLI::App* cmd = analyze->add_subcommand(
      "footprint", "The footprint table (Johnson & McAllister eq. 4) against its erf closed form");
  cmd->add_option("--size", fp->size, "Table size (size x size nodes)")->check(CLI::Range(2, 4096));
  cmd->add_option("--intervals", fp->intervals, "Quadrature intervals along z")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--rule", fp->rule, "Composite rule: trapezoid, simpson or midpoint");
  cmd->add_flag("--json", fp->json, "Print one JSON object");
  cmd->callback([fp] { run_footprint(*fp); });
  add_billboard_mode_analysis(*analyze);
  add_analyze_projection_error_command(*analyze);
  add_analyze_stereo_command(*analyze);
  add_analyze_media_commands(*analyze);
  add_flipbook_commands(app, *analyze);  // also `pyro bake-flipbook`
}

}  // namespace pyro::cli
