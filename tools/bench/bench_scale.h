#pragma once
// How the CPU cost of a frame grows with the particle count: a scene's clouds run at each count,
// the radius scaled by (count0 / count)^(1/3) so that N r^3, and with it the clouds' mean optical
// depth, stays as it was (the cloud keeps its look). Per count, the frame's wall time and the
// CPU work the engine does (simulation, sorting, building the instances, submitting the draws),
// beside baselines measured in the same run on the same data: std::sort of the frame's own sort
// keys with the same order, and a memcpy of the instance bytes.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "components/render_modes.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

struct ScaleBenchOptions {
  std::string scene;
  std::vector<uint64_t> counts{100000, 200000, 500000, 1000000, 1500000, 2000000};
  int frames = 5;   // timed frames per count, after two warm-up frames
  int width = 0, height = 0;  // 0: the scene's size
  int threads = 0;  // the schedule's threads (0: one per core)
  bool cull = true;  // false: every particle sorted and drawn (RenderSettings::cull_particles)
  SortDevice sort_device = SortDevice::automatic;  // where the draw order is made
  ProgressSink* progress = nullptr;
};

// {"scene", "width", "height", "frames", "cull", "sort_device", "counts": [per count: "particles",
// "drawn_particles" (the mean the view's list kept), "ms_per_frame",
// "cpu_ms_per_frame", "driver_ms_per_frame", "system_ms" {name: ms}, "stage_ms" {keys, pack,
// sort, gather, instance_write, instance_wait, draw_calls, submission}, "bytes_per_particle"
// {pools, sort_keys, draw_list, instances}, "sort_ms", "std_sort_ms", "sort_over_std_sort",
// "instances_ms", "memcpy_instances_ms", "instances_over_memcpy", "ordered_on" ("cpu" or
// "gpu": where the last frame's order was made), "sort_device_choice" (under "auto": the
// measurement that chose, {"gpu", "cpu_ms", "gpu_ms", "particles"}, or null)}], "cpu_slope",
// "frame_slope" (log-log least squares over the counts from 1e5 to 2e6, null with fewer than two
// such counts)}.
// cpu_ms_per_frame: the spawn, simulate, camera and sort systems, writing the instances into the
// GPU's memory, and the rest of billboard_render's own work (state, draw submission); not the
// time inside the draw calls (on llvmpipe the driver runs the vertex stage there), the wait for
// a free buffer slot, or the other GL systems: those make driver_ms_per_frame, the rest of the
// frame. instances_ms: everything done to turn the pools into GPU instances (packing and
// gathering for gathered lists, writing into the mapped buffer). An order made on the GPU has no
// CPU keys: "std_sort_ms" and its ratio are then null, and the GPU's work is in the driver's time.
// Throws UserError when the scene has no clouds to scale.
nlohmann::json bench_scale(const ScaleBenchOptions& options);

// The scene with its clouds' counts summing to `count` (each keeps its share) and each radius
// times (old count / new count)^(1/3): N r^3 is kept, and with it the clouds' mean optical
// depth. The particle budget is raised to fit.
SceneDescription scale_clouds(const SceneDescription& scene, uint64_t count);

// The least-squares slope of log y against log x (points with x or y <= 0 are left out); NaN
// with fewer than two distinct x.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace pyro
