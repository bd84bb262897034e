#pragma once
// The data behind the paper's figures 4-13 (Johnson & McAllister 2005, section 3): projection
// and parallax error surfaces over a grid of billboard centres, and the two top-view diagrams
// (figures 6 and 7). Each figure carries its table (written as CSV) and what a chart of it
// needs (written into the manifest that tools/plots/plot_alignment_figures.py reads), so the
// plotting script draws and never computes.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pyro {

struct AlignmentFigureParameters {
  double radius = 0.4;         // r; the paper's particles have r = 0.32 to 0.45 (section 4)
  double near = 1.0;           // N; errors are in viewplane units and scale with N
  double interocular = 0.065;  // I, for figures 10-13 (StereoParameters' default)
  int grid = 61;               // nodes per axis of a surface
};

// The ranges (docs/billboard_alignment.md): with z_near = -(N + 1.25 r)
//   figures 4, 8, 10, 12 (C_x, C_z vary): C_x in [-5, 5], C_z in [z_near - 18.5, z_near];
//     C_y = 0 (4, 10) or 1 (8, 12: e_y is identically zero at C_y = 0);
//   figures 5, 9, 11, 13 (C_x, C_y vary): C_x, C_y in [-5, 5], C_z = z_near - 1.5;
//   figures 6, 7: C = (2, 0, z_near - 10) (distant) and (2, 0, z_near) (near).
// With the defaults (r = 0.4, N = 1): C_z in [-20, -1.5], the C_x C_y plane at C_z = -3.
struct AlignmentFigure {
  int number = 0;
  std::string name;   // "fig4"
  std::string stem;   // file name without extension, "fig04_e_x_over_cx_cz"
  std::string kind;   // "surface" or "diagram"
  std::string title;  // "Figure 4: ..."
  std::vector<std::string> columns;
  std::vector<std::string> row_labels;  // diagrams only: the first column, naming each point
  std::vector<std::vector<double>> rows;
  nlohmann::json chart;  // axes, panels and labels for the plotting script
};

// "fig4" ... "fig13".
std::vector<std::string> alignment_figure_names();

// Builds one figure. Every billboard is checked against billboard_alignment_domain_problem; the
// ranges above keep them all inside the domain for any r >= 0 and N > 0, so the pyro::UserError
// naming `--radius` that a failure would throw is a safety net. Throws pyro::UserError naming
// `--surface` for an unknown name.
AlignmentFigure make_alignment_figure(const std::string& name, const AlignmentFigureParameters& p);

std::string alignment_figure_csv(const AlignmentFigure& figure);

}  // namespace pyro
