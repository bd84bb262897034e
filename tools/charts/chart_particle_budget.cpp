// pyro chart particle-budget: VDB import error targets -> particle count, render time and image
// error, through the same import and measurement as `pyro import-vdb`
// (tools/import/vdb_import_evaluation.h).
#include <filesystem>
#include <sstream>
#include <string>

#include "engine/core/content_path.h"
#include "engine/io/vdb_reader.h"
#include "tools/charts/charts.h"
#include "tools/import/vdb_import_evaluation.h"

namespace pyro {

namespace {

std::string short_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

ChartTable chart_particle_budget(const ParticleBudgetChartOptions& o) {
  std::vector<std::string> files = o.files;
  if (files.empty()) {
    files.push_back(content_path("volumes/sample_cloud.vdb"));
    const std::filesystem::path disney = std::filesystem::path(content_dir()) / ".." / ".." /
                                         "shared" / "data" / "vdb" / "wdas_cloud_sixteenth.vdb";
    if (std::filesystem::exists(disney)) files.push_back(disney.lexically_normal().string());
  }
  ChartTable t;
  t.name = "particle-budget";
  t.title = "VDB import: error target -> particles, render time, image error (" +
            std::to_string(o.width) + "x" + std::to_string(o.height) + ")";
  t.x_label = "ms per splat frame (sort + draw + readback)";
  t.y_label = "image RMSE (linear RGB) against the CPU volume reference";
  t.ground_truth =
      "the CPU reference render of the grid (systems/runtime/reference/volume_reference.h: ray marching "
      "with single-scattered light), as `pyro import-vdb` measures it";
  t.notes = {"same numbers as: pyro import-vdb FILE --error E --width " + std::to_string(o.width) +
             " --height " + std::to_string(o.height) + " --out F.pyrop --json (rmse, particles)"};
  t.extra_columns = {"error_target", "particles", "active_voxels", "import_ms"};
  nlohmann::json files_json = nlohmann::json::array();
  for (const std::string& file : files) {
    const DenseGrid grid = read_vdb_grid(file, {});
    const VdbImportReference reference = make_vdb_import_reference(grid, o.width, o.height);
    const std::string stem = std::filesystem::path(file).stem().string();
    files_json.push_back({{"file", file}, {"active_voxels", grid.active_voxels}});
    for (double target : o.error_targets) {
      const VdbImportResult r = import_and_measure(grid, target, reference, o.repeats);
      ChartTable::Row row;
      row.label = stem + " E=" + short_number(target) + " (" + std::to_string(r.report.particles) + ")";
      row.front = stem;
      row.group = stem;
      row.time = 1000.0 * r.render_seconds;
      row.error = r.rmse;
      row.extra = {target, double(r.report.particles), double(grid.active_voxels),
                   1000.0 * r.import_seconds};
      t.rows.push_back(row);
    }
  }
  t.summary["files"] = files_json;
  mark_pareto_front(t);
  return t;
}

}  // namespace pyro
