// pyro chart layer-resolution: explosion media layers at 1, 1/2, 1/4, 1/8 of the view, with each
// upsampling method of the compositor (Umenhoffer et al. 2006, section 4), measured by
// `pyro bench layers` (tools/bench/bench_layers.cpp) itself, on the paper's view of the
// explosion and on one with the water tower in front of it.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/content_path.h"
#include "tools/bench/bench_layers.h"
#include "tools/charts/charts.h"

namespace pyro {

namespace {

// One view's rows: each upsampling method at each scale, with the error near depth edges, the
// halo and the front of time against edge error (edge_pareto), compared within the view.
std::vector<ChartTable::Row> view_rows(LayersBenchOptions bench) {
  const std::string view = std::filesystem::path(bench.scene).stem().string();
  ChartTable rows;
  for (LayerUpsampling upsampling : {LayerUpsampling::depth_aware, LayerUpsampling::bilinear}) {
    bench.upsampling = upsampling;
    const bool depth_aware = upsampling == LayerUpsampling::depth_aware;
    const nlohmann::json r = bench_layers(bench);
    const std::string method(name_of(upsampling));
    for (const auto& s : r["scales"]) {
      const double scale = s["scale"].get<double>(), fps = s["fps"].get<double>();
      ChartTable::Row row;
      row.label = view + " " + method + " 1/" + std::to_string(static_cast<int>(1.0 / scale + 0.5));
      row.group = method + " (" + view + ")";
      row.front = view;
      row.time = 1000.0 / fps;
      row.error = s["rmse_vs_full"].get<double>();
      // edge_error and halo: engine/math/depth_edge_error.h (bench layers' edge_rmse and halo).
      row.extra = {scale, fps, depth_aware ? 1.0 : 0.0, s["edge_rmse"].get<double>(),
                   s["halo"].get<double>(), 0.0};
      rows.rows.push_back(row);
    }
  }
  ChartTable edges = rows;
  for (ChartTable::Row& r : edges.rows) r.error = r.extra[3];
  mark_pareto_front(edges);
  for (size_t i = 0; i < rows.rows.size(); ++i) rows.rows[i].extra[5] = edges.rows[i].pareto ? 1.0 : 0.0;
  return rows.rows;
}

}  // namespace

ChartTable chart_layer_resolution(const LayerResolutionChartOptions& o) {
  std::vector<std::string> scenes = o.scenes;
  if (scenes.empty())
    for (const char* s : {"scenes/explosion.json", "scenes/explosion_behind_tower.json"})
      scenes.push_back(content_path(s));
  LayersBenchOptions bench;
  bench.width = o.width;
  bench.height = o.height;
  bench.frames = o.frames;
  bench.error_frames = o.error_frames;

  ChartTable t;
  t.name = "layer-resolution";
  t.title = "Explosion media layers: resolution x upsampling (" + std::to_string(o.width) + "x" +
            std::to_string(o.height) + ")";
  t.x_label = "ms per frame";
  t.y_label = "RMSE (linear RGB) against full-resolution layers";
  t.ground_truth =
      "the same frames rendered with full-resolution layers (layer scale 1), as `pyro bench "
      "layers` measures it; the CPU reference renderer does not model the explosion media";
  std::string views;
  for (const std::string& s : scenes) views += (views.empty() ? "" : ", ") + s;
  t.notes = {"scenes (one Pareto front each): " + views + "; " + std::to_string(o.frames) +
                 " timed frames per point, RMSE over " + std::to_string(o.error_frames) + " of them",
             "same numbers as: pyro bench layers SCENE --width " + std::to_string(o.width) +
                 " --height " + std::to_string(o.height) + " --frames " + std::to_string(o.frames) +
                 " --upsampling depth-aware|bilinear --json (ms = 1000 / fps)"};
  // edge_pareto: on the front of time against edge_error, within the row's scene.
  t.extra_columns = {"scale", "fps", "depth_aware", "edge_error", "halo", "edge_pareto"};
  for (const std::string& scene : scenes) {
    bench.scene = scene;
    for (ChartTable::Row& row : view_rows(bench)) t.rows.push_back(std::move(row));
  }
  mark_pareto_front(t);
  return t;
}

}  // namespace pyro
