#include "tools/import/vdb_import_evaluation.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

#include "engine/core/stopwatch.h"
#include "systems/runtime/reference/volume_reference.h"
#include "tools/import/particle_snapshot.h"
#include "systems/runtime/cloud_import/fire_exposure.h"
#include "systems/runtime/cloud_import/grid_framing.h"

namespace pyro {

VdbImportReference make_vdb_import_reference(const DenseGrid& grid, int width, int height,
                                             bool every_view, VolumeEmission emission) {
  VdbImportReference r;
  r.emission = std::move(emission);
  r.medium = default_medium(grid);
  // A fire's smoke is soot (fire_exposure.h).
  if (!r.emission.temperature.empty()) r.medium.albedo = kFireSmokeAlbedo;
  r.width = width;
  r.height = height;
  if (grid.empty()) return r;
  const auto t0 = std::chrono::steady_clock::now();
  r.camera = framing_camera(grid);
  r.light_depth = light_optical_depth(grid, r.medium);
  const std::vector<float>& light = r.light_depth;
  const auto render = [&](const CameraDescription& camera) {
    return render_volume_reference(grid, light, camera_frame(camera, width, height), r.medium, 0.5, 0, nullptr, {},
                                   &r.emission);
  };
  r.image = render(r.camera);
  if (every_view) {
    r.view_cameras = views_around(grid);
    r.view_images.push_back(r.image);  // the first view is the framing camera's
    for (size_t v = 1; v < r.view_cameras.size(); ++v) r.view_images.push_back(render(r.view_cameras[v]));
    r.inside_camera = view_inside(grid);
    if (r.inside_camera) r.inside_image = render(*r.inside_camera);
  }
  r.seconds = seconds_since(t0);
  return r;
}

void measure_views(VdbImportResult& r, const VdbImportReference& reference,
                   const std::function<RgbImage(const CameraDescription&)>& render) {
  r.view_rmse.clear();
  r.rmse_views_mean = r.rmse_views_max = 0.0;
  r.rmse = image_rmse(reference.image, render(reference.camera));
  for (size_t v = 0; v < reference.view_cameras.size(); ++v) {
    // The first view is the framing camera's, measured above.
    r.view_rmse.push_back(v == 0 ? r.rmse : image_rmse(reference.view_images[v], render(reference.view_cameras[v])));
    r.rmse_views_mean += r.view_rmse.back() / double(reference.view_cameras.size());
    r.rmse_views_max = std::max(r.rmse_views_max, r.view_rmse.back());
  }
  if (reference.inside_camera) r.rmse_inside = image_rmse(reference.inside_image, render(*reference.inside_camera));
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
  const glm::vec3 background(opt.medium.background);
  bool first = true;  // the framing view is timed, best of render_repeats
  measure_views(r, reference, [&](const CameraDescription& camera) {
    SnapshotTiming timing;
    const RgbImage image = render_particle_snapshot(r.particles, camera, reference.width, reference.height,
                                                    background, first ? render_repeats : 1, &timing);
    if (first) r.render_seconds = timing.render_seconds;
    first = false;
    return image;
  });
  return r;
}

VdbImportResult import_and_measure(const DenseGrid& grid, double error, const VdbImportReference& reference,
                                   int render_repeats) {
  return import_and_measure_at(grid, tau_tolerance_for_error(error), reference, render_repeats);
}

}  // namespace pyro
