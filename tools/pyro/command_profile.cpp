// pyro profile SCENE [--frames N] [--warmup K] [--width W] [--height H] [--sync-timing] [--json]
//                    [render options]
//
// A profiling run (SceneRuntime with RuntimeOptions::profile): K warm-up frames (shader
// compilation, first allocations; not counted), then N frames, every system timed on the CPU
// and every GL pass on the GPU (timer queries). Prints per system the mean, median, 95th
// percentile and maximum milliseconds, per GPU pass the same plus the fragments it drew
// (GL_SAMPLES_PASSED: fragments that passed the depth test), the live particles per source
// and per medium, and the particle pools' memory. With --json the last line is one object.
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "components/emitter.h"
#include "components/particle_medium.h"
#include "components/particle_set.h"
#include "engine/core/sample_statistics.h"
#include "systems/scene/scene_loader.h"
#include "systems/scene_runtime/scene_runtime.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/render_options.h"

namespace pyro::cli {

namespace {

struct ProfileArgs {
  std::string scene;
  int frames = 30;
  int warmup = 1;
  int width = 0, height = 0;
  bool json = false;
  RuntimeOptions runtime;
};

nlohmann::json statistics_json(const std::vector<double>& ms) {
  const SampleStatistics s = sample_statistics(ms);
  return {{"mean_ms", s.mean}, {"median_ms", s.median}, {"p95_ms", s.p95}, {"min_ms", s.min},
          {"max_ms", s.max}, {"samples", s.count}};
}

// Bytes one particle slot takes in a ParticlePool: the sum of its attribute arrays' elements.
size_t bytes_per_particle_slot() {
  size_t bytes = 0;
  ParticlePool().for_each_array([&](const auto& a) { bytes += sizeof(a[0]); });
  return bytes;
}

void run_profile(const ProfileArgs& a) {
  const SceneDescription scene = load_scene(a.scene);
  RuntimeOptions options = a.runtime;
  options.readback = false;
  options.width_override = a.width;
  options.height_override = a.height;
  options.profile = true;
  SceneRuntime runtime(scene, options);
  const uint64_t first_counted = static_cast<uint64_t>(a.warmup);
  for (int f = 0; f < a.warmup + a.frames; ++f) runtime.step();
  const std::vector<TraceSpan>& trace = runtime.trace();

  // Per frame: CPU ms per system; GPU ms and fragments per pass name (summed over the frame's
  // views, so a stereo frame's two "fire layer" passes count as one).
  std::map<std::string, std::vector<double>> cpu_ms;
  std::map<std::string, std::map<uint64_t, double>> gpu_ms;
  std::map<std::string, std::map<uint64_t, double>> fragments;
  std::vector<std::string> gpu_order;
  std::vector<double> frame_ms;
  for (const TraceSpan& s : trace) {
    if (s.frame < first_counted) continue;
    if (s.track == TraceTrack::cpu) {
      if (s.category == "frame")
        frame_ms.push_back(s.duration_us * 1e-3);
      else
        cpu_ms[s.name].push_back(s.duration_us * 1e-3);
      continue;
    }
    if (!gpu_ms.count(s.name)) gpu_order.push_back(s.name);
    gpu_ms[s.name][s.frame] += s.duration_us * 1e-3;
    if (s.fragments >= 0) fragments[s.name][s.frame] += static_cast<double>(s.fragments);
  }
  const auto values = [](const std::map<uint64_t, double>& m) {
    std::vector<double> v;
    for (const auto& [frame, x] : m) v.push_back(x);
    return v;
  };

  nlohmann::json systems = nlohmann::json::array();
  for (const ecs::SystemStats& st : runtime.schedule().stats()) {
    nlohmann::json row = statistics_json(cpu_ms[st.name]);
    row["name"] = st.name;
    row["phase"] = ecs::phase_name(st.phase);
    if (gpu_ms.count(st.name)) {
      const SampleStatistics g = sample_statistics(values(gpu_ms[st.name]));
      row["gpu_mean_ms"] = g.mean;
      row["gpu_p95_ms"] = g.p95;
    }
    systems.push_back(row);
  }
  nlohmann::json passes = nlohmann::json::array();
  nlohmann::json layers = nlohmann::json::array();
  for (const std::string& name : gpu_order) {
    nlohmann::json row = statistics_json(values(gpu_ms[name]));
    row["name"] = name;
    if (fragments.count(name)) {
      const SampleStatistics fs = sample_statistics(values(fragments[name]));
      row["fragments_mean"] = fs.mean;
      layers.push_back({{"name", name}, {"fragments_mean", fs.mean}, {"fragments_min", fs.min},
                        {"fragments_max", fs.max}});
    }
    passes.push_back(row);
  }

  // Particles after the last frame: per source (cloud, volume or emitter) and per medium.
  uint64_t live = 0, capacity = 0;
  nlohmann::json sources = nlohmann::json::array();
  std::map<std::string, uint64_t> by_medium;
  size_t set_index = 0;
  runtime.world().each<ParticleSet>([&](ecs::Entity e, ParticleSet& set) {
    const Emitter* emitter = runtime.world().try_get<Emitter>(e);
    const std::string name =
        emitter ? emitter->name : "particle set " + std::to_string(set_index);
    ++set_index;
    sources.push_back({{"name", name}, {"live", set.pool.size()}, {"capacity", set.pool.capacity()}});
    live += set.pool.size();
    capacity += set.pool.capacity();
    if (emitter) {
      for (size_t i = 0; i < set.pool.size(); ++i)
        by_medium[std::string(name_of(static_cast<ParticleMedium>(set.pool.medium[i])))] += 1;
    }
  });
  const size_t slot_bytes = bytes_per_particle_slot();
  nlohmann::json particles = {{"live", live}, {"capacity", capacity}, {"sources", sources}};
  if (!by_medium.empty()) particles["by_medium"] = by_medium;
  nlohmann::json memory = {
      {"bytes_per_particle_slot", slot_bytes},
      {"pool_bytes", capacity * slot_bytes},
      {"pool_bytes_per_live_particle",
       live ? double(capacity * slot_bytes) / double(live) : 0.0}};

  const RenderSettings& rs = runtime.settings();
  const SampleStatistics fs = sample_statistics(frame_ms);
  nlohmann::json summary = {{"scene", scene.file},
                            {"frames", a.frames},
                            {"warmup", a.warmup},
                            {"width", rs.width},
                            {"height", rs.height},
                            {"layer_scale", rs.layer_scale},
                            {"sync_timing", a.runtime.sync_timing},
                            {"frame_mean_ms", fs.mean},
                            {"frame_p95_ms", fs.p95},
                            {"systems", systems},
                            {"gpu_passes", passes},
                            {"layers", layers},
                            {"fragment_counter", "GL_SAMPLES_PASSED"},
                            {"particles", particles},
                            {"memory", memory},
                            {"renderer", shared_headless_context().description()}};

  std::printf("%s: %d frames (after %d warm-up) at %dx%d, frame %.2f ms mean, %.2f ms p95\n",
              scene.file.c_str(), a.frames, a.warmup, rs.width, rs.height, fs.mean, fs.p95);
  std::printf("%-20s %-10s %9s %9s %9s %9s %9s\n", "system", "phase", "mean ms", "p95 ms",
              "max ms", "GPU mean", "GPU p95");
  for (const auto& row : systems) {
    std::printf("%-20s %-10s %9.3f %9.3f %9.3f", row["name"].get<std::string>().c_str(),
                row["phase"].get<std::string>().c_str(), row["mean_ms"].get<double>(),
                row["p95_ms"].get<double>(), row["max_ms"].get<double>());
    if (row.contains("gpu_mean_ms"))
      std::printf(" %9.3f %9.3f\n", row["gpu_mean_ms"].get<double>(), row["gpu_p95_ms"].get<double>());
    else
      std::printf(" %9s %9s\n", "-", "-");
  }
  std::printf("%-32s %9s %9s %14s\n", "GPU pass", "mean ms", "p95 ms", "fragments");
  for (const auto& row : passes) {
    std::printf("%-32s %9.3f %9.3f", row["name"].get<std::string>().c_str(),
                row["mean_ms"].get<double>(), row["p95_ms"].get<double>());
    if (row.contains("fragments_mean"))
      std::printf(" %14.0f\n", row["fragments_mean"].get<double>());
    else
      std::printf(" %14s\n", "-");
  }
  std::printf("particles: %llu live of %llu slots; %zu bytes per slot, %.1f bytes of pool per live particle\n",
              static_cast<unsigned long long>(live), static_cast<unsigned long long>(capacity),
              slot_bytes, memory["pool_bytes_per_live_particle"].get<double>());
  for (const auto& s : sources)
    std::printf("  %-18s %llu live of %llu\n", s["name"].get<std::string>().c_str(),
                static_cast<unsigned long long>(s["live"].get<uint64_t>()),
                static_cast<unsigned long long>(s["capacity"].get<uint64_t>()));
  if (a.json) std::printf("%s\n", summary.dump().c_str());
}

}  // namespace

void add_profile_command(CLI::App& app) {
  auto args = std::make_shared<ProfileArgs>();
  CLI::App* cmd = app.add_subcommand(
      "profile", "Time every system and GPU pass over a run of frames: mean and 95th percentile");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required();
  cmd->add_option("--frames", args->frames, "Frames measured (after the warm-up)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--warmup", args->warmup, "Frames run first and not counted")
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--width", args->width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_flag("--sync-timing", args->runtime.sync_timing,
                "Finish the GPU's work after every system, so each system's CPU span includes the "
                "GPU work it issued (removes CPU/GPU overlap)");
  cmd->add_flag("--json", args->json, "Print a JSON summary as the last line");
  add_render_options(cmd, args->runtime);
  cmd->callback([args] { run_profile(*args); });
}

}  // namespace pyro::cli
