#include "tools/bench/bench_layers.h"

#include "engine/math/depth_edge_error.h"
#include "engine/math/image_error.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>
#include <cmath>
#include <vector>

#include "components/frame_image.h"
#include "components/draw_list.h"
#include "components/gpu_frame.h"
#include "components/view.h"
#include "components/render_settings.h"
#include "engine/ecs/world.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/composite/compositor.h"
#include "systems/composite/opaque_view_readback.h"
#include "systems/runtime/scene_runtime/particle_counts.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "engine/core/progress_sink.h"

namespace pyro {

namespace {

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct FrameTiming {
  double fps = 0.0;
  double cpu_ms_per_frame = 0.0;  // all of the process's threads (llvmpipe's included)
};

void choose_methods(SceneRuntime& runtime, bool depth_aware, bool tiles, bool sprites) {
  MediaComposition m;
  m.depth_aware = depth_aware;
  m.tiles = tiles;
  runtime.world().set_resource<MediaComposition>(m);
  runtime.world().resource<RenderSettings>().billboard_sprites = sprites;
}

// `progress` (may be null) advances by one per timed frame, from `done`.
FrameTiming time_layer_frames(const SceneDescription& scene, const RuntimeOptions& options, int frames,
                        nlohmann::json* system_ms, bool depth_aware = true, bool tiles = true,
                        bool sprites = true, ProgressTask* progress = nullptr, size_t done = 0) {
  // behind the front door: times the layer scale and methods its caller sets
  SceneRuntime runtime(scene, options);
  choose_methods(runtime, depth_aware, tiles, sprites);
  runtime.step();  // warm up: shaders, tables, targets
  glFinish();
  const double cpu0 = process_cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) {
    runtime.step();
    if (progress) progress->update(done + size_t(f) + 1);
  }
  glFinish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = process_cpu_seconds() - cpu0;
  if (system_ms)
    for (const auto& st : runtime.schedule().stats()) (*system_ms)[st.name] = st.mean_ms();
  return {frames / seconds, 1000.0 * cpu / frames};
}


bool depth_aware(const LayersBenchOptions& o) { return o.upsampling == LayerUpsampling::depth_aware; }
bool tiles(const LayersBenchOptions& o) { return o.compose == ComposeMode::tiled; }
bool sprites(const LayersBenchOptions& o) { return o.billboards == BillboardGeometry::sprites; }

}  // namespace

nlohmann::json bench_layers(const LayersBenchOptions& o) {
  const SceneDescription scene = load_scene(o.scene);
  RuntimeOptions base;
  base.readback = false;
  base.width_override = o.width;
  base.height_override = o.height;
  nlohmann::json scales = nlohmann::json::array();
  double full_fps = 0.0;
  // Per scale: the timed frames, then the same frames again for the error.
  ProgressTask progress(o.progress, "bench layers", o.scales.size() * 2 * size_t(o.frames));
  size_t done = 0;
  for (float scale : o.scales) {
    RuntimeOptions timed = base;
    timed.layer_scale = scale;
    timed.sync_timing = o.sync_timing;
    nlohmann::json system_ms = nlohmann::json::object();
    progress.stage(done, "scale " + std::to_string(scale).substr(0, 5) + ", timing");
    const FrameTiming timing = time_layer_frames(scene, timed, o.frames, &system_ms, depth_aware(o),
                                           tiles(o), sprites(o), &progress, done);
    const double fps = timing.fps;
    done += size_t(o.frames);
    progress.stage(done, "scale " + std::to_string(scale).substr(0, 5) + ", error");
    if (full_fps == 0.0) full_fps = fps;
    // Error: the same frames rendered at this scale and at full resolution, linear views.
    RuntimeOptions measured_options = timed, reference_options = base;
    measured_options.readback = reference_options.readback = true;
    reference_options.layer_scale = 1.0f;
    // behind the front door: each layer scale against full resolution, as set here
    SceneRuntime measured(scene, measured_options), reference(scene, reference_options);
    choose_methods(measured, depth_aware(o), tiles(o), sprites(o));
    double sum = 0.0, edge_sum = 0.0, halo_sum = 0.0, halo = 0.0;
    int samples = 0;
    const int every = std::max(1, o.frames / std::max(1, o.error_frames));
    for (int f = 0; f < o.frames; ++f) {
      measured.step();
      reference.step();
      progress.update(++done);
      if ((f + 1) % every == 0 && samples < o.error_frames) {
        const std::vector<float>& image = measured.image().rgba;
        const std::vector<float>& truth = reference.image().rgba;
        const double e = rgba_rmse(image, truth);
        // Near the full-resolution scene's depth edges (engine/math/depth_edge_error.h).
        const ecs::World& world = reference.world();
        const OpaqueView opaque = read_opaque_view(
            world.resource<GpuFrame>(), world.resource<View>(), world.resource<EyeDrawLists>());
        const DepthEdgeError edge =
            depth_edge_error({opaque.width, opaque.height, opaque.view_depth, opaque.rgba, truth,
                              image, opaque.particle_far});
        sum += e * e;
        edge_sum += edge.edge_rmse * edge.edge_rmse;
        halo_sum += edge.halo_rms * edge.halo_rms;
        halo = std::max(halo, edge.halo);
        ++samples;
      }
    }
    scales.push_back({{"scale", scale},
                      {"fps", fps},
                      {"cpu_ms_per_frame", timing.cpu_ms_per_frame},
                      {"speedup_vs_full", full_fps > 0.0 ? fps / full_fps : 1.0},
                      {"rmse_vs_full", samples ? std::sqrt(sum / samples) : 0.0},
                      {"edge_rmse", samples ? std::sqrt(edge_sum / samples) : 0.0},
                      {"halo", halo},
                      {"halo_rms", samples ? std::sqrt(halo_sum / samples) : 0.0},
                      {"system_ms", system_ms}});
  }
  return {{"scene", o.scene}, {"width", o.width}, {"height", o.height}, {"frames", o.frames},
          {"error_frames", o.error_frames},
          {"upsampling", name_of(o.upsampling)}, {"compose", name_of(o.compose)},
          {"billboards", name_of(o.billboards)}, {"scales", scales}};
}

nlohmann::json bench_table1(const Table1BenchOptions& o) {
  const SceneDescription scene = load_scene(o.scene);
  uint32_t base_count = 0;
  for (const EmitterDescription& e : scene.emitters)
    for (const EmitterBurst& b : e.emitter.bursts) base_count += b.count;
  const std::array<int, 5> counts = {0, 263, 526, 1052, 1578};
  const std::array<double, 5> paper_planar = {370, 80, 60, 45, 40};
  const std::array<double, 5> paper_spherical = {370, 70, 56, 40, 35};
  nlohmann::json rows = nlohmann::json::array();
  ProgressTask progress(o.progress, "bench table1", counts.size() * 2 * size_t(o.frames));
  size_t done = 0;
  for (size_t i = 0; i < counts.size(); ++i) {
    SceneDescription s = scene;
    const double k = base_count ? static_cast<double>(counts[i]) / base_count : 0.0;
    if (counts[i] == 0) {
      s.emitters.clear();
    } else {
      const float shrink = static_cast<float>(1.0 / std::sqrt(k));
      for (EmitterDescription& e : s.emitters) {
        for (EmitterBurst& b : e.emitter.bursts)
          b.count = static_cast<uint32_t>(std::lround(b.count * k));
        e.emitter.budget = static_cast<uint32_t>(std::lround(e.emitter.budget * k)) + 1;
        Distribution& d = e.emitter.size;
        d.value *= shrink, d.min *= shrink, d.max *= shrink, d.mean *= shrink, d.stddev *= shrink;
      }
      s.environment.particle_budget = static_cast<uint32_t>(counts[i]) + 64;
    }
    nlohmann::json row = {{"particles", counts[i]}, {"paper_planar_fps", paper_planar[i]},
                          {"paper_spherical_fps", paper_spherical[i]}};
    for (ParticleShape shape : {ParticleShape::planar, ParticleShape::spherical}) {
      RuntimeOptions ro;
      ro.readback = false;
      ro.width_override = o.width;
      ro.height_override = o.height;
      ro.layer_scale = 0.5f;
      ro.particles = shape;
      ro.shading = ParticleShading::explosion;
      // behind the front door: Table 1's explosion at the paper's half-resolution layers
      SceneRuntime probe(s, ro);
      probe.step();
      const uint64_t live = live_particles(probe.world());
      const std::string shape_name(name_of(shape));
      progress.stage(done, std::to_string(counts[i]) + " particles, " + shape_name);
      row[shape_name + "_fps"] =
          time_layer_frames(s, ro, o.frames, nullptr, true, true, true, &progress, done).fps;
      done += size_t(o.frames);
      row["live_particles"] = live;
    }
    rows.push_back(row);
  }
  return {{"scene", o.scene}, {"width", o.width}, {"height", o.height}, {"layer_scale", 0.5},
          {"frames", o.frames}, {"rows", rows}};
}

}  // namespace pyro
