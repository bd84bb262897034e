// pyro chart scale: ms per frame against particles, log-log, for a scene's clouds scaled from
// 10^4 to 2*10^6 particles (`pyro bench scale`, tools/bench/bench_scale.h), the CPU work
// and the whole frame, with the least-squares slopes from 10^5 to 2*10^6.
#include <cstdio>
#include <filesystem>
#include <string>

#include "engine/core/content_path.h"
#include "tools/bench/bench_scale.h"
#include "tools/charts/charts.h"

namespace pyro {

namespace {

std::string exact_number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// A benchmark figure, or nan where the benchmark has none (an order made on the GPU has no
// std::sort baseline).
std::string exact_number(const nlohmann::json& v) {
  return v.is_null() ? "nan" : exact_number(v.get<double>());
}

std::string slope_text(const nlohmann::json& slope) {
  return slope.is_null() ? "none (fewer than two counts from 1e5 to 2e6)" : exact_number(slope.get<double>());
}

}  // namespace

ScaleChart chart_scale(const ScaleChartOptions& o) {
  ScaleBenchOptions bench;
  bench.scene = o.scene.empty() ? content_path("scenes/clouds.json") : o.scene;
  bench.counts = o.counts;
  bench.frames = o.frames;
  bench.width = o.width;
  bench.height = o.height;
  bench.progress = o.progress;
  const nlohmann::json r = bench_scale(bench);
  const std::string scene_name = std::filesystem::path(bench.scene).filename().string();
  std::string csv = "# title: " + scene_name + ": ms per frame against particles (" +
                    std::to_string(r["width"].get<int>()) + "x" + std::to_string(r["height"].get<int>()) +
                    ", radius scaled as count^(-1/3))\n";
  csv += "# x: particles\n# y: ms per frame\n";
  csv += "# cpu_slope: " + slope_text(r["cpu_slope"]) + "\n";
  csv += "# frame_slope: " + slope_text(r["frame_slope"]) + "\n";
  csv += "# note: same numbers as: pyro bench scale SCENE --counts ... --frames " +
         std::to_string(o.frames) + " --json; cpu = simulation, camera, sorting, instance copy and "
         "draw submission; the frame adds the GL driver's work\n";
  csv += "particles,ms_per_frame,cpu_ms_per_frame,keys_ms,sort_ms,pack_ms,instance_write_ms,"
         "draw_calls_ms,sort_over_std_sort,instances_over_memcpy,ordered_on_gpu\n";
  for (const nlohmann::json& c : r["counts"]) {
    const nlohmann::json& st = c["stage_ms"];
    csv += exact_number(c["particles"].get<double>()) + "," + exact_number(c["ms_per_frame"]) + "," +
           exact_number(c["cpu_ms_per_frame"]) + "," + exact_number(st["keys"]) + "," + exact_number(st["sort"]) + "," +
           exact_number(st["pack"]) + "," + exact_number(st["instance_write"]) + "," + exact_number(st["draw_calls"]) +
           "," + exact_number(c["sort_over_std_sort"]) + "," + exact_number(c["instances_over_memcpy"]) + "," +
           (c["ordered_on"] == "gpu" ? "1" : "0") + "\n";
  }
  return {csv, r};
}

}  // namespace pyro
