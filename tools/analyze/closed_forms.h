#pragma once
// pyro analyze footprint | blackbody | phase: engine/math's tables and formulas against their
// closed forms. The footprint table of Johnson & McAllister (eq. 4) against its erf closed form;
// the explosion media's black body and phase functions (Umenhoffer et al. 2006, sections 3.1
// and 3.2).
#include <string>

#include "tools/analyze/analysis_report.h"

namespace pyro {

struct FootprintAnalysisOptions {
  int size = 64;
  int intervals = 100;
  std::string rule = "trapezoid";
};

// Throws UserError for an unknown rule, or Simpson's rule over an odd number of intervals.
AnalysisReport analyze_footprint(const FootprintAnalysisOptions& options);

struct BlackbodyAnalysisOptions {
  double temperature = 2856.0;
};

AnalysisReport analyze_blackbody(const BlackbodyAnalysisOptions& options);

struct PhaseAnalysisOptions {
  std::string function = "henyey-greenstein";
  double g = 0.0;
  int cos_intervals = 4096;
  int azimuth_steps = 96;
};

// Throws UserError for an unknown function or an odd number of polar intervals.
AnalysisReport analyze_phase(const PhaseAnalysisOptions& options);

}  // namespace pyro
