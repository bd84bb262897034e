#include "tools/bench/bench_soak.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "components/emitter.h"
#include "components/particle_set.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

#include "engine/core/progress_sink.h"

namespace pyro {

namespace {

// Resident set size from /proc/self/statm (second field, in pages); 0 where unavailable.
uint64_t resident_bytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  unsigned long long size = 0, resident = 0;
  const int n = std::fscanf(f, "%llu %llu", &size, &resident);
  std::fclose(f);
  return n == 2 ? resident * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE)) : 0;
}

// Particle values (every float array of every pool) that are NaN or infinite. Lifetimes may be
// infinite by design (ParticleInit's default): they are not counted.
uint64_t non_finite_values(SceneRuntime& runtime, uint64_t& live) {
  uint64_t bad = 0;
  live = 0;
  runtime.world().each<ParticleSet>([&](ParticleSet& set) {
    const ParticlePool& p = set.pool;
    live += p.size();
    for (const auto* v : {&p.px, &p.py, &p.pz, &p.vx, &p.vy, &p.vz, &p.radius, &p.density, &p.r, &p.g,
                          &p.b, &p.age, &p.temperature, &p.opacity, &p.size0})
      for (std::size_t i = 0; i < p.size(); ++i) bad += std::isfinite((*v)[i]) ? 0 : 1;
    for (std::size_t i = 0; i < p.size(); ++i) bad += std::isnan(p.lifetime[i]) ? 1 : 0;
  });
  return bad;
}

}  // namespace

nlohmann::json bench_soak(const SoakBenchOptions& o) {
  OpenSceneOptions open;  // the scene as every command opens it: its quality pick applied
  open.runtime.readback = false;
  open.runtime.width_override = o.width;
  open.runtime.height_override = o.height;
  const OpenedScene opened = open_scene(o.scene, open);
  SceneRuntime& runtime = *opened.runtime;
  const SceneDescription& scene = runtime.scene();  // as it runs (a pick's time step applied)

  using clock = std::chrono::steady_clock;
  const long tenth = std::max(1L, o.frames / 10);
  double first_ms = 0, last_ms = 0;
  uint64_t non_finite = 0, live = 0, live_first = 0;
  long first_bad = -1;
  // Resident memory is taken after the first frame: it allocates what the driver allocates
  // lazily (shaders, targets) once, which is not growth.
  uint64_t rss_start = 0, rss_max = 0;
  const double dt = 1.0 / scene.frames_per_second;
  long rearms = 0;
  ProgressTask progress(o.progress, "bench soak", size_t(o.frames));
  const auto t_start = clock::now();
  for (long f = 0; f < o.frames; ++f) {
    if (o.rearm_every > 0.0 && f > 0 &&
        std::floor(f * dt / o.rearm_every) > std::floor((f - 1) * dt / o.rearm_every)) {
      runtime.world().each<Emitter>([](Emitter& e) { e.next_burst = 0; });
      ++rearms;
    }
    const auto t0 = clock::now();
    if (o.render_every > 0 && f % o.render_every == 0) runtime.step(); else runtime.simulate_step();
    const double ms = std::chrono::duration<double, std::milli>(clock::now() - t0).count();
    if (f < tenth) first_ms += ms;
    if (f >= o.frames - tenth) last_ms += ms;
    const uint64_t bad = non_finite_values(runtime, live);
    if (f == tenth - 1) live_first = live;
    if (f == 0) rss_start = rss_max = resident_bytes();
    if (bad && first_bad < 0) first_bad = f;
    non_finite += bad;
    if ((f & 1023) == 0) rss_max = std::max(rss_max, resident_bytes());
    progress.update(size_t(f) + 1);
  }
  progress.finish();
  const double seconds = std::chrono::duration<double>(clock::now() - t_start).count();
  const uint64_t rss_end = resident_bytes();
  uint64_t spawned = 0;
  runtime.world().each<Emitter>([&](Emitter& e) { spawned += e.spawned; });
  rss_max = std::max(rss_max, rss_end);
  first_ms /= static_cast<double>(tenth);
  last_ms /= static_cast<double>(tenth);
  return {{"scene", scene.file},
          {"frames", o.frames},
          {"render_every", o.render_every},
          {"seconds", seconds},
          {"non_finite", non_finite},
          {"first_non_finite_frame", first_bad},
          {"rss_start_bytes", rss_start},
          {"rss_end_bytes", rss_end},
          {"rss_max_bytes", rss_max},
          {"rss_growth_bytes", static_cast<int64_t>(rss_end) - static_cast<int64_t>(rss_start)},
          {"ms_per_frame_first_10pct", first_ms},
          {"ms_per_frame_last_10pct", last_ms},
          {"time_growth", first_ms > 0 ? last_ms / first_ms : 0.0},
          {"live_particles_first_10pct_end", live_first},
          {"live_particles_end", live},
          {"rearm_every_seconds", o.rearm_every},
          {"rearms", rearms},
          {"spawned", spawned}};
}

}  // namespace pyro
