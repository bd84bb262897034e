#pragma once
// The data behind one `pyro chart`: one row per setting, with the time it costs (x) and its
// error against a ground truth (y), written as CSV (comment lines first: what was measured and
// against what) and drawn by tools/plots/plot_pareto.py, which marks the Pareto front computed
// here (the `pareto` column), so the script only draws.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pyro {

struct ChartTable {
  std::string name;          // "footprint"
  std::string title;         // chart title
  std::string x_label, y_label;
  std::string ground_truth;  // what the error is measured against (written into the CSV header)
  std::vector<std::string> notes;  // further comment lines for the CSV (commands, conventions)
  // Columns: "label" (names the point), "group" (one colour per group), "time" (x), "error" (y)
  // are always first; chart-specific columns follow; "pareto" is appended by mark_pareto_front.
  std::vector<std::string> extra_columns;
  struct Row {
    std::string label, group;
    double time = 0.0, error = 0.0;
    std::vector<double> extra;  // one value per extra column
    bool pareto = false;
    // false: the setting failed (a blown-up integrator); listed, never on the Pareto front.
    bool usable = true;
    // Rows compete for the Pareto front only with rows of the same key (e.g. one front per
    // scene or per volume, where settings of different inputs are not alternatives).
    std::string front;
  };
  std::vector<Row> rows;
  nlohmann::json summary = nlohmann::json::object();  // chart-specific figures for --json
};

// Sets Row::pareto on the rows no other row of the same `front` key dominates: a row is dominated when another has
// time <= and error <= with at least one strictly smaller. Rows with a non-finite time or error,
// and rows not `usable`, are never on the front (and dominate nothing).
void mark_pareto_front(ChartTable& table);

// The CSV text: comment lines "# title: ", "# x: ", "# y: ", "# ground truth: ", "# note: "
// (one per note; tools/plots/plot_pareto.py reads the first three), then the header
// label,group,time,error,<extra columns>,pareto,usable,front and one line per row (numbers as %.17g, which
// writes inf and nan as such).
std::string chart_csv(const ChartTable& table);

}  // namespace pyro
