// pyro chart scattering: the splats' octaves of multiple scattering, each count drawn and timed
// by the engine, against the path-traced truth (tools/bench/bench_multiple_scattering.h
// measures the same frames from three suns).
#include <algorithm>
#include <chrono>
#include <string>

#include "components/volume_medium.h"
#include "engine/core/content_path.h"
#include "engine/io/vdb_reader.h"
#include "tools/import/relit_particles.h"
#include "tools/bench/sun_directions.h"
#include "tools/charts/charts.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/grid_framing.h"
#include "systems/runtime/reference/path_traced_volume.h"
#include "systems/runtime/reference/world_snapshot.h"

namespace pyro {

namespace {

// The median milliseconds of `frames` frames (each read back, so the GPU finished it).
double median_frame_ms(SceneRuntime& runtime, int frames) {
  runtime.draw_frame(0);  // warm-up
  std::vector<double> ms;
  for (int f = 1; f <= frames; ++f) {
    const auto t = std::chrono::steady_clock::now();
    runtime.draw_frame(f);
    (void)runtime.image();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count());
  }
  std::nth_element(ms.begin(), ms.begin() + ptrdiff_t(ms.size() / 2), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace

ChartTable chart_scattering(const ScatteringChartOptions& o) {
  const std::string file = o.file.empty() ? content_path("volumes/sample_cloud.vdb") : o.file;
  const DenseGrid grid = read_vdb_grid(file);
  VolumeMedium medium;
  medium.extinction = default_extinction(grid);
  medium.albedo = o.albedo;
  medium.ambient = glm::dvec3(0.0);
  medium.light_direction = sun_direction(0, 3);
  const CameraDescription camera = framing_camera(grid);
  PathTraceOptions trace;
  trace.samples_per_pixel = o.samples;
  trace.anisotropy = o.anisotropy;
  const PathTracedImage truth = path_trace_volume(grid, camera_frame(camera, o.width, o.height), medium, trace);
  const std::vector<GaussianParticle> particles = import_keeping_albedo(grid, medium.extinction, o.albedo, 0.03);

  ChartTable t;
  t.name = "scattering";
  t.title = "Octaves of multiple scattering against the path-traced truth (" + std::to_string(o.width) + "x" +
            std::to_string(o.height) + ")";
  t.x_label = "ms per frame (mono, relit every frame)";
  t.y_label = "RMSE (linear RGB) against the path-traced truth";
  t.ground_truth = "multiple scattering path traced through the grid (delta and ratio tracking, Henyey-Greenstein g " +
                   std::to_string(o.anisotropy) + ", albedo " + std::to_string(o.albedo) + ", " +
                   std::to_string(o.samples) + " paths per pixel; Monte Carlo error " +
                   std::to_string(truth.monte_carlo_error) + ")";
  t.notes = {"n octaves: S = sum over i < n of b^i 4 pi p_HG(mu, c^i g) exp(-a^i tau), a 0.25, b 0.5, c 0.5 "
             "(Wrenninge et al. 2013); 1 octave is single scattering with the forward lobe",
             "file: " + file + ", " + std::to_string(particles.size()) + " particles, the sun alone"};
  t.extra_columns = {"octaves"};
  for (int n : o.octaves) {
    ShadowSettings shadows;
    shadows.scattering = {o.anisotropy, {n, 0.25, 0.5, 0.5}};
    SceneRuntime runtime = relit_particles_runtime(particles, medium, {camera, o.width, o.height, true}, shadows);
    ChartTable::Row row;
    row.label = std::to_string(n) + (n == 1 ? " octave" : " octaves");
    row.group = n == 1 ? "single scattering" : "octaves";
    row.time = median_frame_ms(runtime, o.frames);
    runtime.draw_frame(o.frames + 1);
    row.error = image_rmse(rgb_of(runtime.image()), truth.image);
    row.extra = {double(n)};
    t.rows.push_back(row);
  }
  mark_pareto_front(t);
  t.summary = {{"file", file}, {"monte_carlo_error", truth.monte_carlo_error}, {"particles", particles.size()}};
  return t;
}

}  // namespace pyro
