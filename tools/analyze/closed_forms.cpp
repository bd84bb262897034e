#include "tools/analyze/closed_forms.h"

#include "engine/core/format_text.h"
#include "engine/core/user_error.h"
#include "engine/math/blackbody.h"
#include "engine/math/footprint.h"
#include "engine/math/phase_function.h"

namespace pyro {

AnalysisReport analyze_footprint(const FootprintAnalysisOptions& a) {
  QuadratureRule rule{};
  if (!parse_quadrature_rule(a.rule, rule))
    throw UserError("command line", "--rule",
                    "expected trapezoid, simpson or midpoint, found \"" + a.rule + "\"");
  if (rule == QuadratureRule::simpson && a.intervals % 2 != 0)
    throw UserError(
        "command line", "--intervals",
        "Simpson's rule needs an even number of intervals, found " + std::to_string(a.intervals));
  const FootprintTable table = make_footprint_table(a.size, a.intervals, rule);
  const FootprintError e = measure_footprint_error(table);
  AnalysisReport r;
  r.json = {{"size", a.size},
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
  r.text = format_text("footprint table %dx%d, %d %s intervals over [-%g, %g]\n", a.size, a.size,
                       a.intervals, quadrature_rule_name(rule), table.extent, table.extent);
  r.text +=
      format_text("  raw integrals vs erf closed form (quadrature error): %.3e\n", e.max_abs_error);
  r.text += format_text("  scaled table vs scaled closed form:                  %.3e\n",
                        e.max_abs_error_scaled);
  r.text += format_text("  bilinear-sampled table vs exp(-r^2/2), %d^2 points: %.3e\n",
                        e.sample_grid, e.max_abs_error_sampled);
  return r;
}

AnalysisReport analyze_blackbody(const BlackbodyAnalysisOptions& a) {
  const BlackbodyColor c = blackbody_color(a.temperature);
  AnalysisReport r;
  r.json = {{"temperature", a.temperature},
            {"x", c.xy.x},
            {"y", c.xy.y},
            {"XYZ", {c.xyz.x, c.xyz.y, c.xyz.z}},
            {"rgb", {c.rgb.x, c.rgb.y, c.rgb.z}},
            {"in_srgb_gamut", c.in_gamut},
            {"luminance_cd_m2", c.luminance}};
  r.text = format_text("black body at %g K (Planck, CIE 1931 2 deg observer)\n", a.temperature);
  r.text += format_text("  chromaticity x = %.5f, y = %.5f\n", c.xy.x, c.xy.y);
  r.text += format_text("  XYZ (Y = 1)    %.5f %.5f %.5f\n", c.xyz.x, c.xyz.y, c.xyz.z);
  r.text += format_text("  linear sRGB    %.5f %.5f %.5f (max 1%s)\n", c.rgb.x, c.rgb.y, c.rgb.z,
                        c.in_gamut ? "" : "; outside the sRGB gamut, negatives clamped to 0");
  r.text += format_text("  luminance      %.4g cd/m^2\n", c.luminance);
  return r;
}

AnalysisReport analyze_phase(const PhaseAnalysisOptions& a) {
  PhaseFunction f{};
  if (!parse_phase_function(a.function, f))
    throw UserError("command line", "--function",
                    "expected henyey-greenstein or cornette-shanks, found \"" + a.function + "\"");
  if (a.cos_intervals % 2 != 0)
    throw UserError("command line", "--cos-intervals",
                    "Simpson's rule needs an even number of intervals, found " +
                        std::to_string(a.cos_intervals));
  const SphereIntegral s = integrate_over_sphere(f, a.g, a.cos_intervals, a.azimuth_steps);
  const double closed =
      f == PhaseFunction::henyey_greenstein ? a.g : cornette_shanks_mean_cosine(a.g);
  AnalysisReport r;
  r.json = {{"function", phase_function_name(f)},
            {"g", a.g},
            {"integral", s.integral},
            {"mean_cosine", s.mean_cosine},
            {"mean_cosine_closed_form", closed},
            {"cos_intervals", a.cos_intervals},
            {"azimuth_steps", a.azimuth_steps}};
  r.text = format_text("%s, g = %g, quadrature over the sphere (%d x %d)\n", phase_function_name(f),
                       a.g, a.cos_intervals, a.azimuth_steps);
  r.text += format_text("  integral of p dOmega: %.9f\n", s.integral);
  r.text += format_text("  mean cosine:          %.9f (closed form %.9f)\n", s.mean_cosine, closed);
  return r;
}

}  // namespace pyro
