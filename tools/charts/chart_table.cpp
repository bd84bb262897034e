#include "tools/charts/chart_table.h"

#include <cmath>
#include <cstdio>

namespace pyro {

namespace {

bool finite_point(const ChartTable::Row& r) {
  return r.usable && std::isfinite(r.time) && std::isfinite(r.error);
}

bool dominates(const ChartTable::Row& a, const ChartTable::Row& b) {
  return a.time <= b.time && a.error <= b.error && (a.time < b.time || a.error < b.error);
}

std::string table_number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Labels and groups are ours (no commas or quotes), but quote anyway so the file stays CSV.
std::string field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

void mark_pareto_front(ChartTable& table) {
  for (ChartTable::Row& r : table.rows) {
    r.pareto = finite_point(r);
    if (!r.pareto) continue;
    for (const ChartTable::Row& other : table.rows)
      if (other.front == r.front && finite_point(other) && dominates(other, r)) {
        r.pareto = false;
        break;
      }
  }
}

std::string chart_csv(const ChartTable& t) {
  std::string s = "# title: " + t.title + "\n";
  s += "# x: " + t.x_label + "\n";
  s += "# y: " + t.y_label + "\n";
  s += "# ground truth: " + t.ground_truth + "\n";
  for (const std::string& n : t.notes) s += "# note: " + n + "\n";
  s += "label,group,time,error";
  for (const std::string& c : t.extra_columns) s += "," + c;
  s += ",pareto,usable,front\n";
  for (const ChartTable::Row& r : t.rows) {
    s += field(r.label) + "," + field(r.group) + "," + table_number(r.time) + "," + table_number(r.error);
    for (double v : r.extra) s += "," + table_number(v);
    s += r.pareto ? ",1" : ",0";
    s += r.usable ? ",1," : ",0,";
    s += field(r.front) + "\n";
  }
  return s;
}

}  // namespace pyro
