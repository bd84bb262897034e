#include "tools/bench/bench_relight.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "engine/core/stopwatch.h"
#include "engine/core/user_error.h"
#include "engine/io/vdb_reader.h"
#include "tools/import/fitted_import.h"
#include "tools/import/relit_particles.h"
#include "tools/bench/sun_directions.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/grid_framing.h"
#include "systems/runtime/reference/volume_reference.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

namespace {

// The grid's particles, imported once: the octree's isotropic ones, or the fitted anisotropic ones
// (`baked`: as imported, lit for the default sun; `fitted`: the same with the albedo for colour).
struct RelightParticles {
  std::vector<GaussianParticle> isotropic;
  std::vector<AnisotropicGaussian> baked, fitted;
  std::size_t size() const { return isotropic.size() + fitted.size(); }
};

RelightParticles import_particles(const DenseGrid& grid, const VolumeMedium& medium, const RelightBenchOptions& o) {
  RelightParticles p;
  if (!o.fitted) {
    p.isotropic = import_keeping_albedo(grid, medium.extinction, medium.albedo, o.error);
    return p;
  }
  // As pyro import-vdb fits them: its seven views, at the frames' size up to its default 256.
  const VdbImportReference reference =
      make_vdb_import_reference(grid, std::min(o.width, 256), std::min(o.height, 256), true);
  p.baked = import_to_target(grid, o.error, reference).best.fitted;
  p.fitted = p.baked;
  for (AnisotropicGaussian& g : p.fitted) g.color = glm::vec3(float(reference.medium.albedo));
  return p;
}

SceneRuntime relight_runtime(const RelightParticles& particles, const VolumeMedium& medium,
                             const CameraDescription& camera, const RelightBenchOptions& o, bool lit,
                             bool readback) {
  const RelitView view{camera, o.width, o.height, readback};
  const std::optional<ShadowSettings> shadows = lit ? std::optional<ShadowSettings>(o.shadows) : std::nullopt;
  if (!o.fitted) return relit_particles_runtime(particles.isotropic, medium, view, shadows);
  return relit_particles_runtime(lit ? particles.fitted : particles.baked, medium, view, shadows);
}

// Seconds for frames [first, first + count) (the GPU finished each), the sun turning every frame
// when `turn`.
double time_relit_frames(SceneRuntime& runtime, int first, int count, int directions, bool turn) {
  const auto t = std::chrono::steady_clock::now();
  for (int f = first; f < first + count; ++f) {
    if (turn) set_sun(runtime, sun_direction(f % directions, directions));
    runtime.draw_frame(f);
    glFinish();
  }
  return seconds_since(t);
}

struct FrameRates {
  double lit = 0.0, unlit = 0.0;
};

// Both runtimes timed in alternating blocks of about 4 frames, so that the machine's drift falls
// on both alike: frames per second of each over `frames` frames.
FrameRates alternating_frame_rates(SceneRuntime& lit, SceneRuntime& unlit, int frames, int directions) {
  for (SceneRuntime* r : {&lit, &unlit}) {
    r->draw_frame(0);  // warm-up: shaders, tables, targets
    glFinish();
  }
  double lit_seconds = 0.0, unlit_seconds = 0.0;
  for (int first = 1; first <= frames; first += 4) {
    const int count = std::min(4, frames + 1 - first);
    lit_seconds += time_relit_frames(lit, first, count, directions, true);
    unlit_seconds += time_relit_frames(unlit, first, count, directions, false);
  }
  return {frames / lit_seconds, frames / unlit_seconds};
}

}  // namespace

nlohmann::json bench_relight(const RelightBenchOptions& o) {
  ProgressTask progress(o.progress, "bench relight", o.directions + 2);
  progress.stage(0, "read and import");
  std::string note;
  const DenseGrid grid = read_vdb_grid(o.file, {o.grid, o.grid_index}, &note);
  if (!note.empty() && o.on_note) o.on_note(o.file + ": " + note);
  if (grid.empty()) throw UserError(o.file, "grid \"" + grid.name + "\"", "a grid with active voxels to relight");
  auto t = std::chrono::steady_clock::now();
  VolumeMedium medium;  // the reference's: the default albedo, sun and ambient light
  medium.extinction = default_extinction(grid);
  const RelightParticles particles = import_particles(grid, medium, o);
  const double import_seconds = seconds_since(t);
  const CameraDescription camera = framing_camera(grid);

  SceneRuntime relit = relight_runtime(particles, medium, camera, o, true, true);
  nlohmann::json per_direction = nlohmann::json::array();
  double worst = 0.0, reference_seconds = 0.0;
  for (int k = 0; k < o.directions; ++k) {
    progress.stage(1 + k, "direction " + std::to_string(k + 1));
    medium.light_direction = sun_direction(k, o.directions);
    set_sun(relit, medium.light_direction);
    relit.draw_frame(k);
    t = std::chrono::steady_clock::now();
    const RgbImage reference = render_volume_reference(grid, light_optical_depth(grid, medium),
                                                       camera_frame(camera, o.width, o.height), medium);
    reference_seconds += seconds_since(t);
    const double rmse = image_rmse(rgb_of(relit.image()), reference);
    worst = std::max(worst, rmse);
    const glm::dvec3 d = medium.light_direction;
    per_direction.push_back({{"direction", {d.x, d.y, d.z}}, {"rmse_vs_reference", rmse}});
  }
  progress.stage(o.directions + 1, "time relit and unlit frames, alternating");
  SceneRuntime timed = relight_runtime(particles, medium, camera, o, true, false);
  SceneRuntime unlit = relight_runtime(particles, medium, camera, o, false, false);
  const FrameRates rates = alternating_frame_rates(timed, unlit, o.frames, o.directions);
  const double fps = rates.lit, unlit_fps = rates.unlit;
  progress.finish();
  return {{"file", o.file},
          {"particles", particles.size()},
          {"kind", o.fitted ? "fitted" : "isotropic"},
          {"width", o.width},
          {"height", o.height},
          {"shadows", {{"method", name_of(o.shadows.method)}, {"map_size", o.shadows.map_size},
                       {"map_slices", o.shadows.map_slices},
                       {"splat_sunlight", name_of(o.shadows.splat_sunlight)}}},
          {"directions", per_direction},
          {"max_rmse_vs_reference", worst},
          {"fps", fps},
          {"unlit_fps", unlit_fps},
          {"fps_over_unlit", fps / unlit_fps},
          {"import_seconds", import_seconds},
          {"reference_seconds", reference_seconds}};
}

}  // namespace pyro
