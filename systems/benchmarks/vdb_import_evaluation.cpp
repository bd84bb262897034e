#include "systems/benchmarks/vdb_import_evaluation.h"

#include <chrono>

#include "systems/reference/volume_reference.h"
#include "systems/scene_runtime/particle_snapshot.h"
#include "systems/cloud_import/grid_framing.h"

namespace pyro {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

VdbImportReference make_vdb_import_reference(const DenseGrid& grid, int width, int height) {
  VdbImportReference r;
  r.medium = default_medium(grid);
  r.width = width;
  r.height = height;
  if (grid.empty()) return r;
  const auto t0 = std::chrono::steady_clock::now();
  r.camera = framing_camera(grid);
  const CameraFrame frame = camera_frame(r.camera, width, height);
  const std::vector<float> light = light_optical_depth(grid, r.medium);
  r.image = render_volume_reference(grid, light, frame, r.medium);
  r.seconds = seconds_since(t0);
  return r;
}

VdbImportResult import_and_measure(const DenseGrid& grid, double error, const VdbImportReference& reference,
                                   int render_repeats) {
  VdbImportResult r;
  CloudImportOptions opt;
  opt.medium = reference.medium;
  opt.tau_tolerance = r.tau_tolerance = tau_tolerance_for_error(error);
  const auto t0 = std::chrono::steady_clock::now();
  r.particles = import_cloud(grid, opt, &r.report);
  r.import_seconds = seconds_since(t0);
  if (grid.empty()) return r;
  SnapshotTiming timing;
  const RgbImage splat =
      render_particle_snapshot(r.particles, reference.camera, reference.width, reference.height,
                               glm::vec3(opt.medium.background), render_repeats, &timing);
  r.render_seconds = timing.render_seconds;
  r.rmse = image_rmse(reference.image, splat);
  return r;
}

}  // namespace pyro
