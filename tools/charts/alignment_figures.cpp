#include "tools/charts/alignment_figures.h"

#include <cstdio>
#include <functional>
#include <sstream>
#include <utility>

#include <glm/vec3.hpp>

#include "engine/core/user_error.h"
#include "engine/math/billboard_alignment.h"

namespace pyro {

namespace {

// What a surface shows: the geometric value and the value from the paper's printed equations.
struct Quantity {
  const char* column;       // CSV column of the geometric value; "<column>_paper" for the paper's
  const char* symbol;       // for titles and axis labels
  const char* description;  // for titles
  const char* equation;     // the paper's equation it comes from
};

constexpr Quantity kEx{"e_x", "e_x", "horizontal projection error", "eq. 11"};
constexpr Quantity kEy{"e_y", "e_y", "vertical projection error", "eq. 12"};
constexpr Quantity kHorizontalParallax{"horizontal_parallax_error", "horizontal parallax error",
                                       "horizontal parallax error", "eq. 11"};
constexpr Quantity kVerticalParallax{"vertical_parallax_error", "vertical parallax error",
                                     "vertical parallax error", "eq. 12"};

struct SurfaceSpec {
  int number;
  const char* stem;
  const Quantity* quantity;
  bool over_xz;    // true: C_x and C_z vary; false: C_x and C_y vary
  double fixed_y;  // C_y for surfaces over C_x, C_z
};

const SurfaceSpec kSurfaces[] = {
    {4, "fig04_e_x_over_cx_cz", &kEx, true, 0.0},
    {5, "fig05_e_x_over_cx_cy", &kEx, false, 0.0},
    {8, "fig08_e_y_over_cx_cz", &kEy, true, 1.0},
    {9, "fig09_e_y_over_cx_cy", &kEy, false, 0.0},
    {10, "fig10_horizontal_parallax_error_over_cx_cz", &kHorizontalParallax, true, 0.0},
    {11, "fig11_horizontal_parallax_error_over_cx_cy", &kHorizontalParallax, false, 0.0},
    {12, "fig12_vertical_parallax_error_over_cx_cz", &kVerticalParallax, true, 1.0},
    {13, "fig13_vertical_parallax_error_over_cx_cy", &kVerticalParallax, false, 0.0},
};

std::string number_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string figure_number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Ranges (alignment_figures.h): z_near keeps every edge E, of either billboard and seen from
// either eye, at least r/4 beyond the viewplane, because |E_z - C_z| <= r.
double z_near(const AlignmentFigureParameters& p) { return -(p.near + 1.25 * p.radius); }
constexpr double kHalfWidth = 5.0;
constexpr double kDepthSpan = 18.5;
constexpr double kPlaneOffset = 1.5;

void check_domain(const glm::dvec3& c, const AlignmentFigureParameters& p) {
  const std::string why = billboard_alignment_domain_problem(c, p.radius, p.near, p.interocular);
  if (!why.empty())
    throw UserError("command line", "--radius",
                    "the figures need every billboard beyond the viewplane; at C = (" +
                        figure_number(c.x) + ", " + figure_number(c.y) + ", " + figure_number(c.z) +
                        "): " + why);
}

std::pair<double, double> surface_values(const Quantity* q, const glm::dvec3& c,
                                         const AlignmentFigureParameters& p) {
  if (q == &kEx)
    return {projection_error(c, p.radius, p.near).e_x, paper_eq11_e_x(c, p.radius, p.near)};
  if (q == &kEy)
    return {projection_error(c, p.radius, p.near).e_y, paper_eq12_e_y(c, p.radius, p.near)};
  const ParallaxError geometry = parallax_error(c, p.radius, p.near, p.interocular);
  const ParallaxError paper = parallax_error_from_translated_surfaces(
      c, p.interocular,
      [&](const glm::dvec3& at) { return projection_error_paper(at, p.radius, p.near); });
  if (q == &kHorizontalParallax) return {geometry.horizontal, paper.horizontal};
  return {geometry.vertical, paper.vertical};
}

std::string parameters_text(const AlignmentFigureParameters& p, bool stereo) {
  std::string s = "r = " + figure_number(p.radius) + ", N = " + figure_number(p.near);
  if (stereo) s += ", I = " + figure_number(p.interocular);
  return s;
}

AlignmentFigure make_surface(const SurfaceSpec& spec, const AlignmentFigureParameters& p) {
  const Quantity* q = spec.quantity;
  const bool stereo = q == &kHorizontalParallax || q == &kVerticalParallax;
  AlignmentFigure f;
  f.number = spec.number;
  f.name = "fig" + std::to_string(spec.number);
  f.stem = spec.stem;
  f.kind = "surface";
  f.title = "Figure " + std::to_string(spec.number) + ": " + q->description + " as C_x and " +
            (spec.over_xz ? "C_z" : "C_y") + " vary";
  const std::string value = q->column, paper = std::string(q->column) + "_paper";
  f.columns = {"c_x", "c_y", "c_z", value, paper};

  const int n = p.grid;
  const double z_hi = z_near(p), z_lo = z_hi - kDepthSpan, z_plane = z_hi - kPlaneOffset;
  for (int j = 0; j < n; ++j) {
    const double t = static_cast<double>(j) / (n - 1);
    for (int i = 0; i < n; ++i) {
      const double cx = -kHalfWidth + 2.0 * kHalfWidth * i / (n - 1);
      const glm::dvec3 c = spec.over_xz
                               ? glm::dvec3(cx, spec.fixed_y, z_lo + (z_hi - z_lo) * t)
                               : glm::dvec3(cx, -kHalfWidth + 2.0 * kHalfWidth * t, z_plane);
      check_domain(c, p);
      const auto [geometry, printed] = surface_values(q, c, p);
      f.rows.push_back({c.x, c.y, c.z, geometry, printed});
    }
  }
  const std::string fixed =
      spec.over_xz ? "C_y = " + figure_number(spec.fixed_y) : "C_z = " + figure_number(z_plane);
  f.chart = {{"x", "c_x"},
             {"y", spec.over_xz ? "c_z" : "c_y"},
             {"x_label", "C_x (camera coordinates)"},
             {"y_label", spec.over_xz ? "C_z (camera coordinates)" : "C_y (camera coordinates)"},
             {"value_label", std::string(q->symbol) + " (viewplane units)"},
             {"subtitle", fixed + ", " + parameters_text(p, stereo)},
             {"panels",
              nlohmann::json::array(
                  {{{"column", value}, {"label", "from the geometry (= corrected closed form)"}},
                   {{"column", paper},
                    {"label", std::string("from the paper's ") + q->equation + " as printed"}}})}};
  return f;
}

AlignmentFigure make_diagram(int number, const AlignmentFigureParameters& p) {
  const bool distant = number == 6;
  const glm::dvec3 c(2.0, 0.0, distant ? z_near(p) - 10.0 : z_near(p));
  check_domain(c, p);
  AlignmentFigure f;
  f.number = number;
  f.name = "fig" + std::to_string(number);
  f.stem = distant ? "fig06_distant_billboard_top_view" : "fig07_near_billboard_top_view";
  f.kind = "diagram";
  f.title = "Figure " + std::to_string(number) + ": error for a " + (distant ? "distant" : "near") +
            " billboard (top view, xz plane)";
  f.columns = {"point", "x", "y", "z", "x_star", "y_star"};
  const glm::dvec3 e_perp = viewplane_facing_edge(c, p.radius);
  const glm::dvec3 e_bullet = viewpoint_facing_edge(c, p.radius);
  const std::pair<const char*, glm::dvec3> points[] = {
      {"centre", c},
      {"viewplane_facing_left_edge", c - (e_perp - c)},
      {"viewplane_facing_right_edge", e_perp},
      {"viewpoint_facing_left_edge", c - (e_bullet - c)},
      {"viewpoint_facing_right_edge", e_bullet},
  };
  for (const auto& [label, at] : points) {
    const glm::dvec2 star = project_to_viewplane(at, p.near);
    f.row_labels.push_back(label);
    f.rows.push_back({at.x, at.y, at.z, star.x, star.y});
  }
  const ProjectionError e = projection_error(c, p.radius, p.near);
  f.chart = {{"near", p.near},
             {"radius", p.radius},
             {"centre", {c.x, c.y, c.z}},
             {"e_x", e.e_x},
             {"e_x_paper", paper_eq11_e_x(c, p.radius, p.near)},
             {"subtitle", "C = (" + figure_number(c.x) + ", " + figure_number(c.y) + ", " +
                              figure_number(c.z) + "), " + parameters_text(p, false)}};
  return f;
}

}  // namespace

std::vector<std::string> alignment_figure_names() {
  std::vector<std::string> names;
  for (int k = 4; k <= 13; ++k) names.push_back("fig" + std::to_string(k));
  return names;
}

AlignmentFigure make_alignment_figure(const std::string& name, const AlignmentFigureParameters& p) {
  if (name == "fig6") return make_diagram(6, p);
  if (name == "fig7") return make_diagram(7, p);
  for (const SurfaceSpec& spec : kSurfaces)
    if (name == "fig" + std::to_string(spec.number)) return make_surface(spec, p);
  throw UserError("command line", "--surface",
                  "expected fig4 ... fig13 or all, found \"" + name + "\"");
}

std::string alignment_figure_csv(const AlignmentFigure& figure) {
  std::ostringstream out;
  for (size_t k = 0; k < figure.columns.size(); ++k) out << (k ? "," : "") << figure.columns[k];
  out << "\n";
  for (size_t row = 0; row < figure.rows.size(); ++row) {
    bool first = true;
    if (!figure.row_labels.empty()) {
      out << figure.row_labels[row];
      first = false;
    }
    for (double v : figure.rows[row]) {
      out << (first ? "" : ",") << number_text(v);
      first = false;
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace pyro
