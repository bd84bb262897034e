// pyro analyze blackbody --temperature T [--json]
// pyro analyze phase --function henyey-greenstein|cornette-shanks --g G [--json]
// The explosion media's formulas (Umenhoffer et al. 2006, sections 3.1 and 3.2) from
// engine/math, checked against their closed forms.
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/math/blackbody.h"
#include "engine/math/phase_function.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct BlackbodyArgs {
  double temperature = 2856.0;
  bool json = false;
};

void run_blackbody(const BlackbodyArgs& a) {
  const BlackbodyColor c = blackbody_color(a.temperature);
  const nlohmann::json out = {{"temperature", a.temperature},
                              {"x", c.xy.x},
                              {"y", c.xy.y},
                              {"XYZ", {c.xyz.x, c.xyz.y, c.xyz.z}},
                              {"rgb", {c.rgb.x, c.rgb.y, c.rgb.z}},
                              {"in_srgb_gamut", c.in_gamut},
                              {"luminance_cd_m2", c.luminance}};
  if (a.json) {
    write_stdout(out.dump() + "\n");
    return;
  }
  std::printf("black body at %g K (Planck, CIE 1931 2 deg observer)\n", a.temperature);
  std::printf("  chromaticity x = %.5f, y = %.5f\n", c.xy.x, c.xy.y);
  std::printf("  XYZ (Y = 1)    %.5f %.5f %.5f\n", c.xyz.x, c.xyz.y, c.xyz.z);
  std::printf("  linear sRGB    %.5f %.5f %.5f (max 1%s)\n", c.rgb.x, c.rgb.y, c.rgb.z,
              c.in_gamut ? "" : "; outside the sRGB gamut, negatives clamped to 0");
  std::printf("  luminance      %.4g cd/m^2\n", c.luminance);
}

struct PhaseArgs {
  std::string function = "henyey-greenstein";
  double g = 0.0;
  int cos_intervals = 4096;
  int azimuth_steps = 96;
  bool json = false;
};

void run_phase(const PhaseArgs& a) {
  PhaseFunction f{};
  if (!parse_phase_function(a.function, f))
    throw UserError("command line", "--function",
                    "expected henyey-greenstein or cornette-shanks, found \"" + a.function + "\"");
  if (a.cos_intervals % 2 != 0)
    throw UserError("command line", "--cos-intervals",
                    "Simpson's rule needs an even number of intervals, found " + std::to_string(a.cos_intervals));
  const SphereIntegral s = integrate_over_sphere(f, a.g, a.cos_intervals, a.azimuth_steps);
  const double closed = f == PhaseFunction::henyey_greenstein ? a.g : cornette_shanks_mean_cosine(a.g);
  const nlohmann::json out = {{"function", phase_function_name(f)},
                              {"g", a.g},
                              {"integral", s.integral},
                              {"mean_cosine", s.mean_cosine},
                              {"mean_cosine_closed_form", closed},
                              {"cos_intervals", a.cos_intervals},
                              {"azimuth_steps", a.azimuth_steps}};
  if (a.json) {
    write_stdout(out.dump() + "\n");
    return;
  }
  std::printf("%s, g = %g, quadrature over the sphere (%d x %d)\n", phase_function_name(f), a.g,
              a.cos_intervals, a.azimuth_steps);
  std::printf("  integral of p dOmega: %.9f\n", s.integral);
  std::printf("  mean cosine:          %.9f (closed form %.9f)\n", s.mean_cosine, closed);
}

}  // namespace

void add_analyze_media_commands(CLI::App& analyze) {
  auto bb = std::make_shared<BlackbodyArgs>();
  CLI::App* b = analyze.add_subcommand(
      "blackbody", "Black-body colour: Planck's law through the CIE 1931 2 deg observer");
  b->add_option("--temperature", bb->temperature, "Kelvin")->check(CLI::Range(100.0, 1.0e6));
  b->add_flag("--json", bb->json, "Print one JSON object");
  b->callback([bb] { run_blackbody(*bb); });

  auto ph = std::make_shared<PhaseArgs>();
  CLI::App* p = analyze.add_subcommand(
      "phase", "A phase function integrated over the sphere: normalisation and mean cosine");
  p->add_option("--function", ph->function, "henyey-greenstein or cornette-shanks");
  p->add_option("--g", ph->g, "Asymmetry parameter, -1 < g < 1")->check(CLI::Range(-0.999, 0.999));
  p->add_option("--cos-intervals", ph->cos_intervals, "Simpson intervals in the polar cosine (even)")
      ->check(CLI::Range(2, 1000000));
  p->add_option("--azimuth-steps", ph->azimuth_steps, "Midpoint steps in the azimuth")
      ->check(CLI::Range(1, 100000));
  p->add_flag("--json", ph->json, "Print one JSON object");
  p->callback([ph] { run_phase(*ph); });
}

}  // namespace pyro::cli
