// pyro chart footprint: the footprint table (Johnson & McAllister 2005, eqs 1, 3, 4) for every
// table size x quadrature rule x number of intervals.
#include <chrono>
#include <cstdio>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "engine/math/footprint.h"
#include "tools/charts/charts.h"

namespace pyro {

ChartTable chart_footprint(const FootprintChartOptions& o) {
  ChartTable t;
  t.name = "footprint";
  t.title = "Footprint table: size x quadrature rule x intervals";
  t.x_label = "ms to build the table";
  t.y_label = "max error of the raw table, bilinearly sampled, relative to the peak";
  t.ground_truth =
      "the erf closed form sqrt(2 pi) erf(3/sqrt 2) exp(-(x^2+y^2)/2) (engine/math/footprint.h), "
      "not the CPU reference renderer";
  t.notes = {"error: max_rel_error_raw_sampled of `pyro analyze footprint` over a " +
                 std::to_string(o.sample_grid) + "^2 grid; quadrature_error: its max_abs_error "
                 "(raw integrals at the nodes); sampled_error: max_abs_error_sampled (the scaled "
                 "table the GPU uses)",
             "order: log2(quadrature_error(K) / quadrature_error(2K)) at the same rule and size "
             "(2 for trapezoid and midpoint, 4 for Simpson; nan for the last K)",
             "the scaled table the renderer uses does not depend on the intervals: the kernel "
             "is separable and the scaling cancels the quadrature factor"};
  t.extra_columns = {"size", "intervals", "quadrature_error", "sampled_error", "order"};
  nlohmann::json orders = nlohmann::json::object();
  for (QuadratureRule rule : {QuadratureRule::trapezoid, QuadratureRule::simpson, QuadratureRule::midpoint}) {
    const std::string rule_name = quadrature_rule_name(rule);
    for (int size : o.sizes) {
      const size_t first = t.rows.size();
      for (int k : o.intervals) {
        if (rule == QuadratureRule::simpson && k % 2 != 0) continue;
        double best_ms = std::numeric_limits<double>::infinity();
        FootprintTable table;
        for (int r = 0; r < std::max(1, o.repeats); ++r) {
          const auto t0 = std::chrono::steady_clock::now();
          table = make_footprint_table(size, k, rule);
          best_ms = std::min(best_ms, std::chrono::duration<double, std::milli>(
                                          std::chrono::steady_clock::now() - t0).count());
        }
        const FootprintError e = measure_footprint_error(table, o.sample_grid);
        ChartTable::Row row;
        row.label = rule_name + " n=" + std::to_string(size) + " K=" + std::to_string(k);
        row.group = rule_name;
        row.time = best_ms;
        row.error = e.max_rel_error_raw_sampled;
        row.extra = {double(size), double(k), e.max_abs_error, e.max_abs_error_sampled,
                     std::numeric_limits<double>::quiet_NaN()};
        t.rows.push_back(row);
      }
      // Observed order of the quadrature between successive interval counts (doubling).
      for (size_t i = first; i + 1 < t.rows.size(); ++i) {
        const double ratio = t.rows[i + 1].extra[1] / t.rows[i].extra[1];
        t.rows[i].extra[4] = std::log(t.rows[i].extra[2] / t.rows[i + 1].extra[2]) / std::log(ratio);
      }
      if (size == o.sizes.back() && t.rows.size() >= first + 3) {
        // The order over the middle of the range, away from the coarsest rule.
        orders[rule_name] = t.rows[t.rows.size() - 2].extra[4];
      }
    }
  }
  t.summary["quadrature_order"] = orders;
  // Each rule's measured order of convergence, in the title so the chart shows it.
  std::string order_text;
  for (const auto& [rule, order] : orders.items()) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%s %.2f", order_text.empty() ? "" : ", ", rule.c_str(),
                  order.get<double>());
    order_text += buf;
  }
  if (!order_text.empty()) t.title += " (quadrature order: " + order_text + ")";
  mark_pareto_front(t);
  return t;
}

}  // namespace pyro
