#include "tools/bench/bench_scale.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>

#include "components/draw_list.h"
#include "components/render_settings.h"
#include "components/sort_device_choice.h"
#include "engine/core/enum_names.h"
#include "engine/core/user_error.h"
#include "engine/particles/particle_pool.h"
#include "systems/billboard_render/billboard_renderer.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/particle_counts.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "systems/sorting/depth_sort.h"

namespace pyro {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

template <class F>
double median_of(int repeats, F&& timed) {
  std::vector<double> ms;
  for (int r = 0; r < repeats; ++r) ms.push_back(timed());
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  return ms[ms.size() / 2];
}

// std::sort of the keys with the draw order's comparator: the baseline of the radix order.
double std_sort_ms(const std::vector<SortKey>& keys) {
  return median_of(3, [&] {
    std::vector<SortKey> copy = keys;
    const auto start = Clock::now();
    std::sort(copy.begin(), copy.end(), back_to_front);
    return ms_since(start);
  });
}

// A memcpy of `bytes` between two buffers already touched: the floor of building instances.
double memcpy_ms(std::size_t bytes) {
  if (bytes == 0) return 0.0;
  std::vector<unsigned char> from(bytes, 1), to(bytes, 0);
  return median_of(5, [&] {
    const auto start = Clock::now();
    std::memcpy(to.data(), from.data(), bytes);
    return ms_since(start);
  });
}

bool cpu_phase(const std::string& phase) {
  return phase == "spawn" || phase == "simulate" || phase == "light" || phase == "camera" ||
         phase == "sort";
}

// The per-frame means of one count's run.
struct ScaleRun {
  uint64_t particles = 0;
  uint64_t drawn = 0;  // summed over the timed frames: the particles the view's list kept
  double frame_ms = 0.0;
  std::map<std::string, double> system_ms;
  std::map<std::string, std::string> phase;
  SortStageTimes sort;
  ParticlePassCost pass;
  std::vector<SortKey> last_keys;
  bool on_gpu = false;  // the last frame's order was made on the GPU
  std::optional<SortDeviceChoice> choice;
};

void add_frame(SceneRuntime& runtime, double frame_ms, ScaleRun& run) {
  run.frame_ms += frame_ms;
  for (const ecs::SystemStats& st : runtime.schedule().stats()) {
    run.system_ms[st.name] += st.last_ms;
    run.phase[st.name] = phase_name(st.phase);
  }
  ecs::World& world = runtime.world();
  const EyeDrawLists& lists = world.resource<const EyeDrawLists>();
  run.on_gpu = !lists.eyes.empty() && lists.eyes[0].on_gpu;
  const BillboardRenderer* renderer = world.try_resource<const BillboardRenderer>();
  run.drawn += run.on_gpu && renderer ? renderer->gpu_kept() : drawn_particles(world);
  if (const SortScratch* s = world.try_resource<const SortScratch>()) {
    run.sort.keys_ms += s->times.keys_ms;
    run.sort.pack_ms += s->times.pack_ms;
    run.sort.order_ms += s->times.order_ms;
    run.sort.gather_ms += s->times.gather_ms;
  }
  if (const BillboardRenderer* r = world.try_resource<const BillboardRenderer>()) {
    const ParticlePassCost c = r->cost();
    run.pass.upload.copy_ms += c.upload.copy_ms;
    run.pass.upload.wait_ms += c.upload.wait_ms;
    run.pass.upload.bytes += c.upload.bytes;
    run.pass.draw_call_ms += c.draw_call_ms;
  }
}

ScaleRun run_count(const SceneDescription& scene, const ScaleBenchOptions& o, ProgressTask& progress,
                   size_t& done) {
  RuntimeOptions options;
  options.readback = false;
  options.width_override = o.width;
  options.height_override = o.height;
  options.threads = o.threads;
  // behind the front door: a scene scaled to the particle count measured, as written
  SceneRuntime runtime(scene, options);
  runtime.world().resource<RenderSettings>().cull_particles = o.cull;
  runtime.world().resource<RenderSettings>().sort_device = o.sort_device;
  // Warm-up: shaders, tables, first allocations; the second frame is where SortDevice::automatic
  // measures both devices.
  runtime.step();
  runtime.step();
  glFinish();
  ScaleRun run;
  for (const CloudDescription& c : scene.clouds) run.particles += c.count;
  for (int f = 0; f < o.frames; ++f) {
    const auto start = Clock::now();
    runtime.step();
    glFinish();
    add_frame(runtime, ms_since(start), run);
    progress.update(++done);
  }
  if (const auto* c = runtime.world().try_resource<const SortDeviceChoice>(); c && c->measured)
    run.choice = *c;
  // The last frame's sorted keys: every one, or those the view kept.
  if (const SortScratch* s = runtime.world().try_resource<const SortScratch>(); s && !run.on_gpu) {
    if (s->radix.order.size() == s->keys.size()) run.last_keys = s->keys;
    else
      for (const uint32_t k : s->kept_places) run.last_keys.push_back(s->keys[k]);
  }
  return run;
}

nlohmann::json count_report(const ScaleRun& run, int frames) {
  const double n = frames;
  nlohmann::json systems = nlohmann::json::object();
  double cpu_systems = 0.0;
  for (const auto& [name, ms] : run.system_ms) {
    systems[name] = ms / n;
    if (cpu_phase(run.phase.at(name))) cpu_systems += ms / n;
  }
  const double copy = run.pass.upload.copy_ms / n, wait = run.pass.upload.wait_ms / n;
  const double draws = run.pass.draw_call_ms / n;
  const double billboard = run.system_ms.count("billboard_render") ? run.system_ms.at("billboard_render") / n : 0.0;
  // The rest of billboard_render: setting state and issuing the draws.
  const double submission = std::max(0.0, billboard - copy - wait - draws);
  const double cpu = cpu_systems + copy + submission;
  const double frame = run.frame_ms / n;
  const double sort = run.sort.order_ms / n;
  const double standard = run.on_gpu ? 0.0 : std_sort_ms(run.last_keys);
  nlohmann::json choice = nullptr;
  if (run.choice)
    choice = {{"gpu", run.choice->gpu}, {"cpu_ms", run.choice->cpu_ms},
              {"gpu_ms", run.choice->gpu_ms}, {"particles", run.choice->particles}};
  // Building the instances: packing the pools' attributes, gathering them in draw order, copying
  // them into the GPU's memory.
  const double instances = (run.sort.pack_ms + run.sort.gather_ms) / n + copy;
  const auto instance_bytes = static_cast<std::size_t>(double(run.pass.upload.bytes) / n);
  const double baseline = memcpy_ms(instance_bytes);
  const double per = run.particles > 0 ? 1.0 / double(run.particles) : 0.0;
  return {{"particles", run.particles},
          {"drawn_particles", double(run.drawn) / n},
          {"ms_per_frame", frame},
          {"cpu_ms_per_frame", cpu},
          {"driver_ms_per_frame", std::max(0.0, frame - cpu)},
          {"system_ms", systems},
          {"stage_ms",
           {{"keys", run.sort.keys_ms / n}, {"pack", run.sort.pack_ms / n}, {"sort", sort},
            {"gather", run.sort.gather_ms / n},
            {"instance_write", copy}, {"instance_wait", wait}, {"draw_calls", draws},
            {"submission", submission}}},
          {"bytes_per_particle",
           {{"pools", ParticlePool::bytes_per_slot()},
            {"sort_keys", kSortBytesPerKey + sizeof(uint32_t)},  // and the kept list's places
            {"draw_list", 2 * sizeof(glm::vec4)},
            {"instances", double(instance_bytes) * per}}},
          {"sort_ms", sort},
          {"std_sort_ms", run.on_gpu ? nlohmann::json(nullptr) : nlohmann::json(standard)},
          {"sort_over_std_sort", standard > 0.0 ? nlohmann::json(sort / standard) : nlohmann::json(nullptr)},
          {"ordered_on", run.on_gpu ? "gpu" : "cpu"},
          {"sort_device_choice", choice},
          {"instances_ms", instances},
          {"memcpy_instances_ms", baseline},
          {"instances_over_memcpy", baseline > 0.0 ? instances / baseline : 0.0}};
}

nlohmann::json slope_over(const nlohmann::json& counts, const char* field) {
  std::vector<double> x, y;
  for (const nlohmann::json& c : counts) {
    const double p = c["particles"].get<double>();
    if (p < 1e5 * 0.999 || p > 2e6 * 1.001) continue;
    x.push_back(p);
    y.push_back(c[field].get<double>());
  }
  const double slope = log_log_slope(x, y);
  return std::isfinite(slope) ? nlohmann::json(slope) : nlohmann::json(nullptr);
}

}  // namespace

SceneDescription scale_clouds(const SceneDescription& base, uint64_t count) {
  SceneDescription scene = base;
  double total = 0.0;
  for (const CloudDescription& c : base.clouds) total += c.count;
  uint64_t particles = 0;
  for (CloudDescription& c : scene.clouds) {
    const double share = double(c.count) / total;
    const auto scaled = static_cast<uint32_t>(std::max(1.0, std::round(share * double(count))));
    c.radius *= static_cast<float>(std::cbrt(double(c.count) / double(scaled)));
    c.count = scaled;
    particles += scaled;
  }
  scene.budget.particles = std::max(scene.budget.particles, 2 * particles);
  return scene;
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    if (!(x[i] > 0.0) || !(y[i] > 0.0)) continue;
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    ++n;
  }
  const double d = n * sxx - sx * sx;
  if (n < 2 || !(std::abs(d) > 1e-12)) return std::numeric_limits<double>::quiet_NaN();
  return (n * sxy - sx * sy) / d;
}

nlohmann::json bench_scale(const ScaleBenchOptions& o) {
  const SceneDescription base = load_scene(o.scene);
  if (base.clouds.empty())
    throw UserError(o.scene, "clouds",
                    "bench scale scales a scene's clouds (count and radius); this scene has none");
  ProgressTask progress(o.progress, "bench scale", o.counts.size() * size_t(o.frames));
  size_t done = 0;
  nlohmann::json counts = nlohmann::json::array();
  int width = 0, height = 0;
  for (uint64_t count : o.counts) {
    const SceneDescription scene = scale_clouds(base, count);
    progress.stage(done, std::to_string(count) + " particles");
    counts.push_back(count_report(run_count(scene, o, progress, done), o.frames));
    width = o.width > 0 ? o.width : scene.width;
    height = o.height > 0 ? o.height : scene.height;
  }
  return {{"scene", o.scene},
          {"width", width},
          {"height", height},
          {"frames", o.frames},
          {"cull", o.cull},
          {"sort_device", std::string(name_of(o.sort_device))},
          {"counts", counts},
          {"cpu_slope", slope_over(counts, "cpu_ms_per_frame")},
          {"frame_slope", slope_over(counts, "ms_per_frame")}};
}

}  // namespace pyro
