#include "systems/benchmarks/vdb_import_evaluation.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "systems/reference/volume_reference.h"
#include "systems/scene_runtime/particle_snapshot.h"
#include "systems/cloud_import/grid_framing.h"

namespace pyro {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

VdbImportReference make_vdb_import_reference(const DenseGrid& grid, int width, int height,
                                             bool every_view) {
  VdbImportReference r;
  r.medium = default_medium(grid);
  r.width = width;
  r.height = height;
  if (grid.empty()) return r;
  const auto t0 = std::chrono::steady_clock::now();
  r.camera = framing_camera(grid);
  const std::vector<float> light = light_optical_depth(grid, r.medium);
  r.image = render_volume_reference(grid, light, camera_frame(r.camera, width, height), r.medium);
  if (every_view) {
    r.view_cameras = views_around(grid);
    r.view_images.push_back(r.image);  // the first view is the framing camera's
    for (size_t v = 1; v < r.view_cameras.size(); ++v)
      r.view_images.push_back(
          render_volume_reference(grid, light, camera_frame(r.view_cameras[v], width, height), r.medium));
    r.inside_camera = view_inside(grid);
    if (r.inside_camera)
      r.inside_image = render_volume_reference(grid, light, camera_frame(*r.inside_camera, width, height), r.medium);
  }
  r.seconds = seconds_since(t0);
  return r;
}

VdbImportResult import_and_measure_at(const DenseGrid& grid, double tau_tolerance,
                                      const VdbImportReference& reference, int render_repeats) {
  VdbImportResult r;
  CloudImportOptions opt;
  opt.medium = reference.medium;
  opt.tau_tolerance = r.tau_tolerance = tau_tolerance;
  const auto t0 = std::chrono::steady_clock::now();
  r.particles = import_cloud(grid, opt, &r.report);
  r.import_seconds = seconds_since(t0);
  if (grid.empty()) return r;
  SnapshotTiming timing;
  const glm::vec3 background(opt.medium.background);
  const RgbImage splat = render_particle_snapshot(r.particles, reference.camera, reference.width,
                                                  reference.height, background, render_repeats, &timing);
  r.render_seconds = timing.render_seconds;
  r.rmse = image_rmse(reference.image, splat);
  for (size_t v = 0; v < reference.view_cameras.size(); ++v) {
    const RgbImage view = v == 0 ? splat
                                 : render_particle_snapshot(r.particles, reference.view_cameras[v],
                                                            reference.width, reference.height, background);
    r.view_rmse.push_back(image_rmse(reference.view_images[v], view));
    r.rmse_views_mean += r.view_rmse.back() / double(reference.view_cameras.size());
    r.rmse_views_max = std::max(r.rmse_views_max, r.view_rmse.back());
  }
  if (reference.inside_camera)
    r.rmse_inside = image_rmse(reference.inside_image,
                               render_particle_snapshot(r.particles, *reference.inside_camera, reference.width,
                                                        reference.height, background));
  return r;
}

VdbImportResult import_and_measure(const DenseGrid& grid, double error, const VdbImportReference& reference,
                                   int render_repeats) {
  return import_and_measure_at(grid, tau_tolerance_for_error(error), reference, render_repeats);
}

FittedImport import_to_target(const DenseGrid& grid, double error, const VdbImportReference& reference,
                              int max_refinements) {
  FittedImport fit;
  double tolerance = tau_tolerance_for_error(error);
  fit.best = import_and_measure_at(grid, tolerance, reference);
  int stalled = 0;  // refinements in a row that did not lower the error clearly
  while (!(fit.best.rmse_views_max <= error)) {
    if (fit.refinements == max_refinements) {
      fit.reason = "stopped after " + std::to_string(max_refinements) + " refinements of the octree";
      return fit;
    }
    tolerance *= 0.5;
    ++fit.refinements;
    VdbImportResult finer = import_and_measure_at(grid, tolerance, reference);
    const bool grew = finer.report.particles > fit.best.report.particles;
    // A finer import replaces the best one only where it meets the target or is clearly better
    // (2 %), so a miss does not end with many more particles for nothing.
    const bool better = finer.rmse_views_max <= error || finer.rmse_views_max < 0.98 * fit.best.rmse_views_max;
    stalled = better ? 0 : stalled + 1;
    if (better) fit.best = std::move(finer);
    if (!grew) {
      fit.reason = "the octree has reached its finest particles (a tighter tolerance adds none): "
                   "isotropic Gaussians of at least one voxel cannot fit this grid closer";
      return fit;
    }
    if (stalled == 2) {
      char text[256];
      std::snprintf(text, sizeof text,
                    "the error has stopped falling near %.4f: a finer octree adds particles without "
                    "lowering it (the floor of isotropic Gaussians on this grid)",
                    fit.best.rmse_views_max);
      fit.reason = text;
      return fit;
    }
  }
  fit.target_met = true;
  return fit;
}

}  // namespace pyro
