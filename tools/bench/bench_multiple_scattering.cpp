#include "tools/bench/bench_multiple_scattering.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "components/volume_medium.h"
#include "engine/core/stopwatch.h"
#include "engine/core/user_error.h"
#include "engine/io/png_file.h"
#include "engine/io/vdb_reader.h"
#include "tools/import/relit_particles.h"
#include "tools/bench/sun_directions.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/grid_framing.h"
#include "systems/runtime/reference/path_traced_volume.h"
#include "systems/runtime/reference/volume_reference.h"
#include "systems/runtime/reference/world_snapshot.h"

namespace pyro {

namespace {

void write_frame(const std::string& folder, const std::string& name, const RgbImage& img) {
  std::vector<float> rgba(size_t(4) * img.width * img.height, 1.0f);
  for (size_t i = 0; i < size_t(img.width) * img.height; ++i)
    for (int c = 0; c < 3; ++c) rgba[4 * i + c] = img.rgb[3 * i + c];
  write_png((std::filesystem::path(folder) / name).string(), img.width, img.height, 3,
            linear_rgba_to_srgb8(rgba, img.width, img.height));
}

void check_octaves(const MultipleScatteringBenchOptions& o) {
  try {
    validate(o.sun);
  } catch (const std::invalid_argument& e) {
    throw UserError("", "--anisotropy, --octaves, --attenuation, --contribution, --eccentricity", e.what());
  }
}

// The engine's frames: the imported particles lit by the light phase with `sun`.
struct EngineFrames {
  SceneRuntime single, octaves;
};

EngineFrames engine_frames(const std::vector<GaussianParticle>& particles, const VolumeMedium& medium,
                           const CameraDescription& camera, const MultipleScatteringBenchOptions& o) {
  SunScattering single = o.sun;
  single.octaves.octaves = 1;
  const RelitView view{camera, o.width, o.height, true};
  ShadowSettings shadows;
  shadows.method = o.shadow_method;
  shadows.scattering = single;
  SceneRuntime a = relit_particles_runtime(particles, medium, view, shadows);
  shadows.scattering = o.sun;
  return {std::move(a), relit_particles_runtime(particles, medium, view, shadows)};
}

RgbImage engine_frame(SceneRuntime& runtime, const glm::dvec3& sun, int frame) {
  set_sun(runtime, sun);
  runtime.draw_frame(frame);
  return rgb_of(runtime.image());
}

// One sun direction: the truth, the two ray marches and the engine's two frames, scored.
nlohmann::json score_scattering_direction(const DenseGrid& grid, const VolumeMedium& medium, const CameraFrame& camera,
                               const MultipleScatteringBenchOptions& o, EngineFrames& engine, int k) {
  SunScattering single = o.sun;
  single.octaves.octaves = 1;
  PathTraceOptions trace;
  trace.samples_per_pixel = o.samples;
  trace.anisotropy = o.sun.anisotropy;
  trace.threads = o.threads;
  const PathTracedImage truth = path_trace_volume(grid, camera, medium, trace);
  const std::vector<float> depth = light_optical_depth(grid, medium, 0.5, o.threads);
  const RgbImage ss = render_volume_reference(grid, depth, camera, medium, 0.5, o.threads, nullptr, single);
  const auto t = std::chrono::steady_clock::now();
  const RgbImage ms = render_volume_reference(grid, depth, camera, medium, 0.5, o.threads, nullptr, o.sun);
  const double ms_seconds = seconds_since(t);
  const RgbImage engine_ss = engine_frame(engine.single, medium.light_direction, k);
  const RgbImage engine_ms = engine_frame(engine.octaves, medium.light_direction, k);
  if (!o.images.empty()) {
    const std::string tag = "direction" + std::to_string(k + 1);
    write_frame(o.images, tag + "_path_traced.png", truth.image);
    write_frame(o.images, tag + "_single_scattering.png", ss);
    write_frame(o.images, tag + "_octaves.png", ms);
    write_frame(o.images, tag + "_engine_single_scattering.png", engine_ss);
    write_frame(o.images, tag + "_engine_octaves.png", engine_ms);
  }
  const glm::dvec3 d = medium.light_direction;
  return {{"direction", {d.x, d.y, d.z}},
          {"path_traced_seconds", truth.seconds},
          {"monte_carlo_error", truth.monte_carlo_error},
          {"truncated_paths", truth.truncated_paths},
          {"single_scattering_rmse", image_rmse(ss, truth.image)},
          {"octaves_rmse", image_rmse(ms, truth.image)},
          {"octaves_seconds", ms_seconds},
          {"engine_single_rmse", image_rmse(engine_ss, truth.image)},
          {"engine_octaves_rmse", image_rmse(engine_ms, truth.image)}};
}

}  // namespace

nlohmann::json bench_multiple_scattering(const MultipleScatteringBenchOptions& o) {
  check_octaves(o);
  ProgressTask progress(o.progress, "bench multiple-scattering", size_t(o.directions) + 1);
  progress.stage(0, "read and import");
  std::string note;
  const DenseGrid grid = read_vdb_grid(o.file, {o.grid, o.grid_index}, &note);
  if (!note.empty() && o.on_note) o.on_note(o.file + ": " + note);
  if (grid.empty()) throw UserError(o.file, "grid \"" + grid.name + "\"", "a grid with active voxels to light");
  VolumeMedium medium;
  medium.extinction = o.extinction > 0.0 ? o.extinction : default_extinction(grid);
  medium.albedo = o.albedo;
  medium.ambient = glm::dvec3(0.0);
  const std::vector<GaussianParticle> particles =
      import_keeping_albedo(grid, medium.extinction, medium.albedo, o.error);
  const CameraDescription framing = framing_camera(grid);
  EngineFrames engine = engine_frames(particles, medium, framing, o);
  const CameraFrame camera = camera_frame(framing, o.width, o.height);

  nlohmann::json per_direction = nlohmann::json::array();
  double worst_single = 0.0, worst_octaves = 0.0;
  bool closer = true, engine_closer = true;
  for (int k = 0; k < o.directions; ++k) {
    progress.stage(1 + size_t(k), "direction " + std::to_string(k + 1) + " of " + std::to_string(o.directions));
    medium.light_direction = sun_direction(k, o.directions);
    nlohmann::json j = score_scattering_direction(grid, medium, camera, o, engine, k);
    worst_single = std::max(worst_single, j["single_scattering_rmse"].get<double>());
    worst_octaves = std::max(worst_octaves, j["octaves_rmse"].get<double>());
    closer = closer && j["octaves_rmse"].get<double>() < j["single_scattering_rmse"].get<double>();
    engine_closer = engine_closer && j["engine_octaves_rmse"].get<double>() < j["engine_single_rmse"].get<double>();
    per_direction.push_back(std::move(j));
  }
  progress.finish();
  const ScatteringOctaves& oct = o.sun.octaves;
  return {{"file", o.file},
          {"grid", grid.name},
          {"particles", particles.size()},
          {"width", o.width},
          {"height", o.height},
          {"samples", o.samples},
          {"extinction", medium.extinction},
          {"albedo", medium.albedo},
          {"anisotropy", o.sun.anisotropy},
          {"octaves", {{"count", oct.octaves}, {"attenuation", oct.attenuation},
                       {"contribution", oct.contribution}, {"eccentricity", oct.eccentricity}}},
          {"directions", per_direction},
          {"max_single_scattering_rmse", worst_single},
          {"max_octaves_rmse", worst_octaves},
          {"octaves_closer_everywhere", closer},
          {"engine_octaves_closer_everywhere", engine_closer}};
}

}  // namespace pyro
