#pragma once
// A profiling run's figures (pyro profile; an embedding program's own reports): from a
// runtime that ran with RuntimeOptions::profile, per system the mean, median, 95th percentile,
// minimum and maximum CPU milliseconds (and the GPU milliseconds of its pass), per GPU pass the
// same and the fragments it drew (summed over a frame's views), the frame times, and the live
// particles per source and per medium with the pools' memory. Frames before `first_frame` (the
// warm-up) are left out.
#include <cstdint>

#include <nlohmann/json.hpp>

#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

// Fields: frame_mean_ms, frame_p95_ms, systems [{name, phase, mean_ms, median_ms, p95_ms,
// min_ms, max_ms, samples, gpu_mean_ms?, gpu_p95_ms?}], gpu_passes [{name, ... , fragments_mean?}],
// layers [{name, fragments_mean, fragments_min, fragments_max}], fragment_counter, particles
// {live, capacity, sources [{name, live, capacity}], by_medium?}, memory {bytes_per_particle_slot,
// pool_bytes, pool_bytes_per_live_particle}.
nlohmann::json profile_report(SceneRuntime& runtime, uint64_t first_frame);

}  // namespace pyro
