#include "systems/benchmarks/bench_multiple_scattering.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "components/volume_medium.h"
#include "engine/core/user_error.h"
#include "engine/io/png_file.h"
#include "engine/io/vdb_reader.h"
#include "systems/benchmarks/sun_directions.h"
#include "systems/cloud_import/cloud_import.h"
#include "systems/cloud_import/grid_framing.h"
#include "systems/reference/path_traced_volume.h"
#include "systems/reference/volume_reference.h"

namespace pyro {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void write_frame(const std::string& folder, const std::string& name, const RgbImage& img) {
  std::vector<float> rgba(size_t(4) * img.width * img.height, 1.0f);
  for (size_t i = 0; i < size_t(img.width) * img.height; ++i)
    for (int c = 0; c < 3; ++c) rgba[4 * i + c] = img.rgb[3 * i + c];
  write_png((std::filesystem::path(folder) / name).string(), img.width, img.height, 3,
            linear_rgba_to_srgb8(rgba, img.width, img.height));
}

SunScattering checked(const MultipleScatteringBenchOptions& o) {
  try {
    validate(o.sun);
  } catch (const std::invalid_argument& e) {
    throw UserError("bench multiple-scattering", "the octave parameters", e.what());
  }
  return o.sun;
}

}  // namespace

nlohmann::json bench_multiple_scattering(const MultipleScatteringBenchOptions& o) {
  const SunScattering octaves = checked(o);
  SunScattering single = octaves;
  single.octaves.octaves = 1;
  ProgressTask progress(o.progress, "bench multiple-scattering", size_t(o.directions) + 1);
  progress.stage(0, "read");
  std::string note;
  const DenseGrid grid = read_vdb_grid(o.file, {o.grid, o.grid_index}, &note);
  if (!note.empty() && o.on_note) o.on_note(o.file + ": " + note);
  if (grid.empty()) throw UserError(o.file, "grid \"" + grid.name + "\"", "a grid with active voxels to light");
  VolumeMedium medium;
  medium.extinction = o.extinction > 0.0 ? o.extinction : default_extinction(grid);
  medium.albedo = o.albedo;
  medium.ambient = glm::dvec3(0.0);
  const CameraFrame camera = camera_frame(framing_camera(grid), o.width, o.height);
  PathTraceOptions trace;
  trace.samples_per_pixel = o.samples;
  trace.anisotropy = octaves.anisotropy;
  trace.threads = o.threads;

  nlohmann::json per_direction = nlohmann::json::array();
  double worst_single = 0.0, worst_octaves = 0.0;
  bool closer_everywhere = true;
  for (int k = 0; k < o.directions; ++k) {
    progress.stage(1 + size_t(k), "direction " + std::to_string(k + 1) + " of " + std::to_string(o.directions));
    medium.light_direction = sun_direction(k, o.directions);
    const PathTracedImage truth = path_trace_volume(grid, camera, medium, trace);
    const std::vector<float> depth = light_optical_depth(grid, medium, 0.5, o.threads);
    const RgbImage ss = render_volume_reference(grid, depth, camera, medium, 0.5, o.threads, nullptr, single);
    const auto t = std::chrono::steady_clock::now();
    const RgbImage ms = render_volume_reference(grid, depth, camera, medium, 0.5, o.threads, nullptr, octaves);
    const double ms_seconds = seconds_since(t);
    const double ss_rmse = image_rmse(ss, truth.image), ms_rmse = image_rmse(ms, truth.image);
    worst_single = std::max(worst_single, ss_rmse);
    worst_octaves = std::max(worst_octaves, ms_rmse);
    closer_everywhere = closer_everywhere && ms_rmse < ss_rmse;
    if (!o.images.empty()) {
      const std::string tag = "direction" + std::to_string(k + 1);
      write_frame(o.images, tag + "_path_traced.png", truth.image);
      write_frame(o.images, tag + "_single_scattering.png", ss);
      write_frame(o.images, tag + "_octaves.png", ms);
    }
    const glm::dvec3 d = medium.light_direction;
    per_direction.push_back({{"direction", {d.x, d.y, d.z}},
                             {"path_traced_seconds", truth.seconds},
                             {"monte_carlo_error", truth.monte_carlo_error},
                             {"truncated_paths", truth.truncated_paths},
                             {"single_scattering_rmse", ss_rmse},
                             {"octaves_rmse", ms_rmse},
                             {"octaves_seconds", ms_seconds}});
  }
  progress.finish();
  return {{"file", o.file},
          {"grid", grid.name},
          {"width", o.width},
          {"height", o.height},
          {"samples", o.samples},
          {"extinction", medium.extinction},
          {"albedo", medium.albedo},
          {"anisotropy", octaves.anisotropy},
          {"octaves", {{"count", octaves.octaves.octaves}, {"attenuation", octaves.octaves.attenuation},
                       {"contribution", octaves.octaves.contribution},
                       {"eccentricity", octaves.octaves.eccentricity}}},
          {"directions", per_direction},
          {"max_single_scattering_rmse", worst_single},
          {"max_octaves_rmse", worst_octaves},
          {"octaves_closer_everywhere", closer_everywhere}};
}

}  // namespace pyro
