// pyro chart shadows --density: each shadow method and map size on a cumulus that thickens, the
// error against the CPU reference with exact shadows as the optical depth across one particle
// grows, beside each setting's time.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "tools/charts/charts.h"
#include "tools/bench/frame_timing.h"
#include "systems/runtime/quality/quality_settings.h"
#include "systems/runtime/quality_picker/quality_measurement.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

namespace {

// content/scenes/clouds.json's cumulus with 10,000 particles of density rho, lit with shadows.
SceneDescription dense_cumulus(double rho, int width, int height) {
  char density[32];
  std::snprintf(density, sizeof density, "%.17g", rho);
  return parse_scene(std::string(R"({"name": "dense cumulus", "seed": 14,
      "output": {"width": )") + std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(},
      "background": [0.35, 0.55, 0.85],
      "camera": {"position": [1.5, 2.2, 14.0], "target": [0.0, 3.6, 0.0], "fov_y_deg": 45},
      "light": {"direction": [-0.5, -1.0, -0.35], "color": [1.0, 0.97, 0.9], "ambient": [0.3, 0.35, 0.45]},
      "clouds": [{"count": 10000, "radius": 0.37, "color": 0.86, "jitter": 0.02, "density": )" + density +
                         R"(, "box": {"min": [-6.0, 4.0, -6.0], "max": [6.0, 7.5, 6.0]}}],
      "meshes": [{"type": "ground_plane", "scale": 40, "color": [0.3, 0.36, 0.25]}],
      "shadows": {"method": "map"}})",
                     "dense cumulus (pyro chart shadows --density)");
}

std::vector<ShadowSettings> density_candidates(const std::vector<int>& map_sizes) {
  std::vector<ShadowSettings> out(2);
  out[0].method = ShadowMethod::none;
  out[1].method = ShadowMethod::rays;
  for (int size : map_sizes) {
    ShadowSettings s;
    s.map_size = size;
    s.map_slices = std::max(4, size / 2);
    out.push_back(s);
  }
  return out;
}

std::string density_setting_name(const ShadowSettings& s) {
  if (s.method != ShadowMethod::shadow_map) return std::string(name_of(s.method));
  return "map " + std::to_string(s.map_size) + "x" + std::to_string(s.map_slices);
}

// Per setting, the first density (ascending) whose error exceeds the target; null: none does.
nlohmann::json where_each_leaves_the_target(const ChartTable& t, double target) {
  nlohmann::json leaves = nlohmann::json::object();
  for (const ChartTable::Row& row : t.rows) {
    if (!leaves.contains(row.group)) leaves[row.group] = nullptr;
    if (leaves[row.group].is_null() && !(row.error <= target)) leaves[row.group] = row.extra[0];
  }
  return leaves;
}

}  // namespace

ChartTable chart_shadow_density(const ShadowDensityChartOptions& o) {
  ChartTable t;
  t.name = "shadows";
  t.title = "Shadow methods as the medium thickens: a 10,000-particle cumulus (" + std::to_string(o.width) + "x" +
            std::to_string(o.height) + ")";
  t.x_label = "optical depth through one particle's centre, tau0 = -ln(1 - rho)";
  t.y_label = "RMSE (linear RGB) against the CPU reference with exact shadows";
  t.ground_truth =
      "single scattering of the sun with its transmittance exact at every point of every ray "
      "(systems/runtime/reference/lit_particle_reference.h)";
  char target[48];
  std::snprintf(target, sizeof target, "target: %g", o.target);
  t.notes = {std::string(target) + "; the summary's leaves_target is each setting's first density whose error exceeds it",
             "time: ms per frame (mono, the median of the timed frames); none: lit without shadows; rays: "
             "exact transmittance at each particle, linearized across it; map SxK: the opacity map, "
             "read per fragment where the eye sees a thick particle (tau0 >= 1)"};
  t.extra_columns = {"density", "tau0"};
  for (double rho : o.densities) {
    const SceneDescription scene = dense_cumulus(rho, o.width, o.height);
    const QualityGroundTruth truth(scene, o.width, o.height, {0});
    char front[32];
    std::snprintf(front, sizeof front, "rho %g", rho);
    for (const ShadowSettings& s : density_candidates(o.map_sizes)) {
      QualitySettings q;
      q.shadows = shadow_choice(s);
      RuntimeOptions ro;
      ro.width_override = o.width;
      ro.height_override = o.height;
      ChartTable::Row row;
      row.group = density_setting_name(s);
      row.label = std::string(front) + " " + row.group;
      row.front = front;
      row.error = measure_rmse(scene, o.width, o.height, q, truth);
      SceneDescription timed = scene;
      timed.shadows = s;
      row.time = median_ms_per_frame(timed, ro, o.frames);
      row.extra = {rho, -std::log(std::max(1.0 - rho, 1e-12))};  // as billboard.vert clamps it
      t.rows.push_back(row);
    }
  }
  mark_pareto_front(t);
  t.summary = {{"target", o.target}, {"leaves_target", where_each_leaves_the_target(t, o.target)}};
  return t;
}

}  // namespace pyro
