// pyro analyze blackbody --temperature T [--json]
// pyro analyze phase --function henyey-greenstein|cornette-shanks --g G [--json]
// The explosion media's formulas (Umenhoffer et al. 2006, sections 3.1 and 3.2) from
// engine/math, checked against their closed forms (tools/analyze/closed_forms.h).
#include <memory>

#include "tools/analyze/closed_forms.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct BlackbodyArgs {
  BlackbodyAnalysisOptions options;
  bool json = false;
};

struct PhaseArgs {
  PhaseAnalysisOptions options;
  bool json = false;
};

}  // namespace

void add_analyze_media_commands(CLI::App& analyze) {
  auto bb = std::make_shared<BlackbodyArgs>();
  CLI::App* b = analyze.add_subcommand(
      "blackbody", "Black-body colour: Planck's law through the CIE 1931 2 deg observer");
  b->add_option("--temperature", bb->options.temperature, "Kelvin")->check(CLI::Range(100.0, 1.0e6));
  b->add_flag("--json", bb->json, "Print one JSON object");
  b->callback([bb] { write_result(analyze_blackbody(bb->options), bb->json); });

  auto ph = std::make_shared<PhaseArgs>();
  CLI::App* p = analyze.add_subcommand(
      "phase", "A phase function integrated over the sphere: normalisation and mean cosine");
  p->add_option("--function", ph->options.function, "henyey-greenstein or cornette-shanks");
  p->add_option("--g", ph->options.g, "Asymmetry parameter, -1 < g < 1")->check(CLI::Range(-0.999, 0.999));
  p->add_option("--cos-intervals", ph->options.cos_intervals, "Simpson intervals in the polar cosine (even)")
      ->check(CLI::Range(2, 1000000));
  p->add_option("--azimuth-steps", ph->options.azimuth_steps, "Midpoint steps in the azimuth")
      ->check(CLI::Range(1, 100000));
  p->add_flag("--json", ph->json, "Print one JSON object");
  p->callback([ph] { write_result(analyze_phase(ph->options), ph->json); });
}

}  // namespace pyro::cli
