#pragma once
// The profiler panel (Dear ImGui): the frame rate, each system's milliseconds and each GPU
// pass's fragments over the last seconds as plots (frame_time_history.h), the particles live
// and drawn per source, and what the scene's assets cost (files read, reused, flipbooks baked).
#include <cstdint>
#include <string>
#include <vector>

#include "systems/runtime/scene_runtime/particle_counts.h"
#include "tools/viewer/docked_panel.h"
#include "tools/viewer/frame_time_history.h"

namespace pyro {

struct ProfilerView {
  double fps = 0.0, frame_ms = 0.0;
  uint64_t frame = 0;
  size_t drawn = 0;
  ParticleCensus census;
  const FrameTimeHistory* systems = nullptr;    // milliseconds per system
  const FrameTimeHistory* fragments = nullptr;  // fragments per GPU pass (empty: not profiling)
  std::vector<std::pair<std::string, uint64_t>> asset_counters;
  bool gpu_profiling = false;
};

struct ProfilerRequest {
  bool toggle_gpu_profiling = false;
};

ProfilerRequest draw_profiler_panel(const ProfilerView& view, DockedPanel& panel);

}  // namespace pyro
