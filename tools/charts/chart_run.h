#pragma once
// pyro chart NAME --out DIR: one chart measured (charts.h), written as DIR/NAME.csv (atomically)
// and drawn as DIR/NAME.png by tools/plots/plot_pareto.py (the scale chart: its own CSV and
// plot_scale.py), with a report of its points.
#include <nlohmann/json.hpp>
#include <string>

#include "engine/core/progress_sink.h"

namespace pyro {

struct ChartRunOptions {
  std::string name, out;
  int width = 0, height = 0, frames = 0;  // 0: the chart's default
  bool csv_only = false;
  bool density = false;  // shadows only: against the medium's density (chart_shadow_density)
  ProgressSink* progress = nullptr;
};

struct ChartReport {
  nlohmann::json json;
  std::string text;
};

// Checks `out` before any measuring (UserError, IoError), refuses an option the chart does not
// use, measures, then writes and draws.
ChartReport run_chart(const ChartRunOptions& options);

}  // namespace pyro
