#include "tools/bench/bench_explosion_shadows.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "components/fire_lights.h"
#include "components/frame_image.h"
#include "components/render_settings.h"
#include "engine/core/user_error.h"
#include "engine/math/image_error.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

namespace {

// The frames (1-based step counts) where the error is measured: `count` spread over `frames`.
std::vector<int> error_frames(int frames, int count) {
  std::vector<int> at;
  const int every = std::max(1, frames / std::max(1, count));
  for (int f = every; f <= frames && int(at.size()) < count; f += every) at.push_back(f);
  return at;
}

SceneDescription with_shadows(SceneDescription scene, const std::optional<ShadowSettings>& shadows) {
  scene.shadows = shadows;
  return scene;
}

RuntimeOptions runtime_options(const ExplosionShadowsBenchOptions& o, float layer_scale, bool readback) {
  RuntimeOptions ro;
  ro.readback = readback;
  ro.width_override = o.width;
  ro.height_override = o.height;
  ro.layer_scale = layer_scale;
  return ro;
}

// The images at `at` of `scene` stepped from its start.
std::vector<std::vector<float>> images_at(const SceneDescription& scene, const RuntimeOptions& ro,
                                          const std::vector<int>& at, bool cull) {
  // behind the front door: times and images the shadow settings this benchmark sets itself
  SceneRuntime runtime(scene, ro);
  runtime.world().resource<RenderSettings>().cull_particles = cull;
  std::vector<std::vector<float>> images;
  for (int f = 1; f <= at.back(); ++f) {
    runtime.step();
    if (std::find(at.begin(), at.end(), f) != at.end()) images.push_back(runtime.image().rgba);
  }
  return images;
}

double rmse_against(const std::vector<std::vector<float>>& images, const std::vector<std::vector<float>>& truth) {
  double sum = 0.0;
  for (size_t i = 0; i < images.size(); ++i) {
    const double e = rgba_rmse(images[i], truth[i]);
    sum += e * e;
  }
  return images.empty() ? 0.0 : std::sqrt(sum / double(images.size()));
}

// `frames` steps of `runtime`, the GPU finished every frame: seconds.
double timed_steps(SceneRuntime& runtime, int frames) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) {
    runtime.step();
    glFinish();
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct PairedRates {
  double off_fps = 0.0, lit_fps = 0.0;
};

// Frames per second of `off` and `lit` over `frames` steps each (after a warm-up step), timed
// in alternating blocks of a tenth, so that the machine's drift (other load, clocks) falls on
// both alike and their ratio holds.
PairedRates paired_frames_per_second(const SceneDescription& off, const SceneDescription& lit,
                                     const RuntimeOptions& ro, int frames) {
  // behind the front door: the same scene unlit and lit, at the settings this benchmark sets
  SceneRuntime a(off, ro), b(lit, ro);
  a.step();
  b.step();
  glFinish();
  const int block = std::max(1, frames / 10);
  double off_seconds = 0.0, lit_seconds = 0.0;
  for (int done = 0; done < frames; done += block) {
    const int n = std::min(block, frames - done);
    off_seconds += timed_steps(a, n);
    lit_seconds += timed_steps(b, n);
  }
  return {frames / off_seconds, frames / lit_seconds};
}

}  // namespace

nlohmann::json bench_explosion_shadows(const ExplosionShadowsBenchOptions& o) {
  const SceneDescription scene = load_scene(o.scene);
  if (scene.render.shading != ParticleShading::explosion || scene.render.particles == ParticleShape::gaussian)
    throw UserError(o.scene, "/render", "an explosion's media (\"shading\": \"explosion\" with spherical or planar particles)");
  const std::vector<int> at = error_frames(o.frames, o.error_frames);
  ProgressTask progress(o.progress, "bench explosion-shadows", 2 * o.settings.size() + 2);
  size_t done = 0;
  progress.stage(done++, "truth: exact shadows per fragment, full-resolution layers");
  ShadowSettings exact;
  exact.exact_fragments = true;
  exact.fire_lights = kMaxFireLights;  // computed, though the exact shaders read every emitter
  const std::vector<std::vector<float>> truth =
      images_at(with_shadows(scene, exact), runtime_options(o, 1.0f, true), at, false);
  const RuntimeOptions timed = runtime_options(o, o.layer_scale, false), measured = runtime_options(o, o.layer_scale, true);
  const SceneDescription off = with_shadows(scene, std::nullopt);
  progress.stage(done++, "shadows off, error");
  const double off_rmse = rmse_against(images_at(off, measured, at, true), truth);
  double off_fps = 0.0;
  nlohmann::json rows = nlohmann::json::array();
  for (const ShadowSettings& s : o.settings) {
    const std::string name = std::string(name_of(s.method)) + " " + std::to_string(s.map_size) + "x" +
                             std::to_string(s.map_slices) + ", " + std::to_string(s.fire_lights) + " fire lights";
    const SceneDescription lit = with_shadows(scene, s);
    progress.stage(done++, name + ", timed beside shadows off");
    const PairedRates rates = paired_frames_per_second(off, lit, timed, o.frames);
    off_fps = std::max(off_fps, rates.off_fps);
    progress.stage(done++, name + ", error");
    const double rmse = rmse_against(images_at(lit, measured, at, true), truth);
    rows.push_back({{"method", name_of(s.method)}, {"map_size", s.map_size}, {"map_slices", s.map_slices},
                    {"fire_lights", s.fire_lights}, {"fps", rates.lit_fps}, {"off_fps", rates.off_fps},
                    {"fps_over_off", rates.lit_fps / rates.off_fps}, {"rmse_vs_truth", rmse}});
  }
  progress.finish();
  return {{"scene", o.scene},      {"width", o.width},
          {"height", o.height},    {"layer_scale", o.layer_scale},
          {"frames", o.frames},    {"error_frames", at.size()},
          {"off", {{"fps", off_fps}, {"rmse_vs_truth", off_rmse}}},
          {"settings", rows}};
}

}  // namespace pyro
