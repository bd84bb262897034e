#include "tools/bench/profile_report.h"

#include <map>
#include <string>
#include <vector>

#include "engine/core/sample_statistics.h"
#include "engine/core/trace_events.h"
#include "engine/particles/particle_pool.h"
#include "systems/runtime/scene_runtime/particle_counts.h"

namespace pyro {

namespace {

nlohmann::json statistics_json(const std::vector<double>& ms) {
  const SampleStatistics s = sample_statistics(ms);
  return {{"mean_ms", s.mean}, {"median_ms", s.median}, {"p95_ms", s.p95}, {"min_ms", s.min},
          {"max_ms", s.max}, {"samples", s.count}};
}

// The trace's spans from `first_frame` on, grouped: CPU ms per system and per frame; GPU ms and
// fragments per pass name and frame (summed over the frame's views, so a stereo frame's two
// "fire layer" passes count as one).
struct GroupedSpans {
  std::map<std::string, std::vector<double>> cpu_ms;
  std::map<std::string, std::map<uint64_t, double>> gpu_ms, fragments;
  std::vector<std::string> gpu_order;  // pass names in first-seen order
  std::vector<double> frame_ms;
};

GroupedSpans group_spans(const std::vector<TraceSpan>& trace, uint64_t first_frame) {
  GroupedSpans g;
  for (const TraceSpan& s : trace) {
    if (s.frame < first_frame) continue;
    if (s.track == TraceTrack::cpu) {
      if (s.category == "frame") g.frame_ms.push_back(s.duration_us * 1e-3);
      else g.cpu_ms[s.name].push_back(s.duration_us * 1e-3);
      continue;
    }
    if (!g.gpu_ms.count(s.name)) g.gpu_order.push_back(s.name);
    g.gpu_ms[s.name][s.frame] += s.duration_us * 1e-3;
    if (s.fragments >= 0) g.fragments[s.name][s.frame] += static_cast<double>(s.fragments);
  }
  return g;
}

std::vector<double> values(const std::map<uint64_t, double>& m) {
  std::vector<double> v;
  for (const auto& [frame, x] : m) v.push_back(x);
  return v;
}

nlohmann::json system_rows(const ecs::Schedule& schedule, GroupedSpans& g) {
  nlohmann::json systems = nlohmann::json::array();
  for (const ecs::SystemStats& st : schedule.stats()) {
    nlohmann::json row = statistics_json(g.cpu_ms[st.name]);
    row["name"] = st.name;
    row["phase"] = ecs::phase_name(st.phase);
    if (g.gpu_ms.count(st.name)) {
      const SampleStatistics gpu = sample_statistics(values(g.gpu_ms[st.name]));
      row["gpu_mean_ms"] = gpu.mean;
      row["gpu_p95_ms"] = gpu.p95;
    }
    systems.push_back(row);
  }
  return systems;
}

void add_pass_rows(nlohmann::json& report, GroupedSpans& g) {
  nlohmann::json passes = nlohmann::json::array(), layers = nlohmann::json::array();
  for (const std::string& name : g.gpu_order) {
    nlohmann::json row = statistics_json(values(g.gpu_ms[name]));
    row["name"] = name;
    if (g.fragments.count(name)) {
      const SampleStatistics fs = sample_statistics(values(g.fragments[name]));
      row["fragments_mean"] = fs.mean;
      layers.push_back({{"name", name}, {"fragments_mean", fs.mean}, {"fragments_min", fs.min},
                        {"fragments_max", fs.max}});
    }
    passes.push_back(row);
  }
  report["gpu_passes"] = passes;
  report["layers"] = layers;
  report["fragment_counter"] = "GL_SAMPLES_PASSED";
}

void add_particles(nlohmann::json& report, ecs::World& world) {
  const ParticleCensus census = count_particles(world);
  nlohmann::json sources = nlohmann::json::array();
  for (const ParticleSourceCount& s : census.sources)
    sources.push_back({{"name", s.name}, {"live", s.live}, {"capacity", s.capacity}});
  nlohmann::json particles = {{"live", census.live}, {"capacity", census.capacity}, {"sources", sources}};
  if (!census.by_medium.empty()) particles["by_medium"] = census.by_medium;
  const size_t slot_bytes = ParticlePool::bytes_per_slot();
  const uint64_t pool_bytes = census.capacity * slot_bytes;
  report["particles"] = particles;
  report["memory"] = {
      {"bytes_per_particle_slot", slot_bytes},
      {"pool_bytes", pool_bytes},
      {"pool_bytes_per_live_particle", census.live ? double(pool_bytes) / double(census.live) : 0.0}};
}

}  // namespace


nlohmann::json profile_report(SceneRuntime& runtime, uint64_t first_frame) {
  GroupedSpans g = group_spans(runtime.trace(), first_frame);
  const SampleStatistics frames = sample_statistics(g.frame_ms);
  nlohmann::json report = {{"frame_mean_ms", frames.mean}, {"frame_p95_ms", frames.p95}};
  report["systems"] = system_rows(runtime.schedule(), g);
  add_pass_rows(report, g);
  add_particles(report, runtime.world());
  return report;
}

}  // namespace pyro
