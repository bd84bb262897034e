#pragma once
// pyro analyze projection-error: the billboard alignment error of Johnson & McAllister 2005,
// section 3 (engine/math/billboard_alignment.h, docs/billboard_alignment.md), for one billboard,
// or as the error surfaces of the paper's figures 4-13 written as CSV (with the manifest
// alignment_figures.json) and drawn as PNG charts by tools/plots/plot_alignment_figures.py
// (Debian's matplotlib, /usr/bin/python3).
#include <string>

#include "engine/core/progress_sink.h"
#include "tools/analyze/analysis_report.h"
#include "tools/charts/alignment_figures.h"

namespace pyro {

struct ProjectionErrorOptions {
  double cx = 0.0, cy = 0.0, cz = 0.0;  // the billboard's centre, camera coordinates
  double radius = AlignmentFigureParameters{}.radius;
  double near = AlignmentFigureParameters{}.near;
  double interocular = AlignmentFigureParameters{}.interocular;
  int grid = AlignmentFigureParameters{}.grid;
  std::string surface;  // fig4 ... fig13, or all
  std::string out;      // the folder for the figures
  bool csv_only = false;
  ProgressSink* progress = nullptr;
};

// One billboard at (cx, cy, cz): the errors by geometry, as printed in the paper and in
// corrected closed form, and the parallax errors. UserError outside the formulas' domain.
AnalysisReport analyze_projection_error(const ProjectionErrorOptions& options);

// The figures named by `surface`, all computed before any is written into `out` (UserError
// when `out` is empty or cannot be made), then drawn unless csv_only.
AnalysisReport write_projection_error_figures(const ProjectionErrorOptions& options);

}  // namespace pyro
