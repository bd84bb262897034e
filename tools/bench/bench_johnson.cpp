#include "tools/bench/bench_johnson.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "components/camera.h"
#include "engine/math/image_error.h"
#include "systems/runtime/scene/scene_loader.h"
#include "engine/core/content_path.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "engine/core/progress_sink.h"

namespace pyro {

namespace {

struct PaperScene {
  uint32_t particles;
  float radius;
  double paper_avg_fps;  // GeForce 4, 2005
};

constexpr PaperScene kScenes[] = {{1000, 0.4f, 50.0}, {2000, 0.4f, 14.0}, {2000, 0.32f, 20.0}};

// The fog scene's box and look, with the paper's particle counts and radii.
SceneDescription johnson_scene(const PaperScene& p, int width, int height) {
  SceneDescription s = load_scene(content_path("scenes/fog.json"));
  s.name = "johnson " + std::to_string(p.particles) + " r=" + std::to_string(p.radius);
  s.width = width;
  s.height = height;
  s.clouds.at(0).count = p.particles;
  s.clouds.at(0).radius = p.radius;
  s.clouds.at(0).drift = {0, 0, 0};
  s.clouds.at(0).jitter = 0;
  s.camera.zero_parallax_distance = 6.0f;
  s.camera.interocular = 0.12f;
  return s;
}

// The scripted path: from outside the box (z = 13) straight through it to z = -3, at the
// height of the tower's legs, looking along -z.
void place_viewer(SceneRuntime& r, double t) {
  const float z = static_cast<float>(13.0 - 16.0 * t);
  r.world().each<Camera>([&](Camera& c) {
    c.position = {0.8f, 2.0f, z};
    c.target = {0.8f, 2.0f, z - 1.0f};
  });
}


}  // namespace

nlohmann::json bench_johnson(const JohnsonBenchOptions& o) {
  nlohmann::json scenes = nlohmann::json::array();
  ProgressTask progress(o.progress, "bench johnson", std::size(kScenes) * static_cast<size_t>(o.frames));
  size_t done = 0;
  for (const PaperScene& p : kScenes) {
    const SceneDescription scene = johnson_scene(p, o.width, o.height);
    RuntimeOptions ro;
    ro.readback = false;
    ro.stereo_mode = StereoMode::anaglyph;
    ro.layer_scale = o.layer_scale;
    ro.frame_scale = o.frame_scale;
    ro.sync_timing = o.sync_timing;
    // behind the front door: the paper's scenes at the layer and frame scales asked for
    SceneRuntime runtime(scene, ro);
    place_viewer(runtime, 0.0);
    runtime.step();  // warm up
    glFinish();
    std::vector<double> ms;
    for (int f = 0; f < o.frames; ++f) {
      place_viewer(runtime, static_cast<double>(f) / std::max(1, o.frames - 1));
      const auto t0 = std::chrono::steady_clock::now();
      runtime.step();
      glFinish();
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      progress.update(++done);
    }
    double total = 0.0;
    for (double m : ms) total += m;
    const double worst = *std::max_element(ms.begin(), ms.end());

    // What the reduced layer costs in accuracy: the same frames at full resolution.
    nlohmann::json errors = nlohmann::json::array();
    double max_rmse = 0.0;
    if ((o.layer_scale < 1.0f || o.frame_scale < 1.0f) && o.error_samples > 0) {
      RuntimeOptions reduced = ro, full = ro;
      reduced.sync_timing = full.sync_timing = false;
      full.layer_scale = 1.0f;
      full.frame_scale = 1.0f;
      // behind the front door: reduced against full resolution, as set here
      SceneRuntime measured(scene, reduced), reference(scene, full);
      for (int k = 0; k < o.error_samples; ++k) {
        const double t = (k + 0.5) / o.error_samples;
        place_viewer(measured, t);
        place_viewer(reference, t);
        measured.step();
        reference.step();
        const double e = srgb8_rmse(measured.read_output().rgba, reference.read_output().rgba);
        max_rmse = std::max(max_rmse, e);
        errors.push_back({{"path_t", t}, {"rmse", e}});
      }
    }
    nlohmann::json systems = nlohmann::json::object();
    for (const auto& st : runtime.schedule().stats()) systems[st.name] = st.mean_ms();
    scenes.push_back({{"particles", p.particles},
                      {"system_ms", systems},
                      {"radius", p.radius},
                      {"avg_fps", 1000.0 * o.frames / total},
                      {"min_fps", 1000.0 / worst},
                      {"paper_avg_fps", p.paper_avg_fps},
                      {"ratio_to_paper", 1000.0 * o.frames / total / p.paper_avg_fps},
                      {"layer_scale", o.layer_scale},
                      {"frame_scale", o.frame_scale},
                      {"max_rmse_vs_full_resolution", max_rmse},
                      {"rmse_samples", errors}});
  }
  progress.finish();
  return {{"width", o.width},
          {"height", o.height},
          {"stereo", name_of(StereoMode::anaglyph)},
          {"frames", o.frames},
          {"scenes", scenes},
          {"renderer", shared_headless_context().description()}};
}

}  // namespace pyro
