#pragma once
// Profiling a runtime (RuntimeOptions::profile): a "frame" span per frame on the
// CPU track with the systems' spans inside it (from the schedule's stats), and the GPU passes
// on the GPU track (timer queries, read a frame late so that reading rarely waits).
#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/core/trace_events.h"
#include "engine/ecs/schedule.h"
#include "engine/gpu/gpu_pass_timer.h"

namespace pyro {

class RuntimeProfiler {
 public:
  // Needs the runtime's OpenGL context to be current. Time 0 of the trace is now.
  RuntimeProfiler();

  // While it lives, the render passes report to this profiler's GPU timer.
  class FrameScope {
   public:
    explicit FrameScope(gpu::GpuPassTimer* timer) { gpu::set_active_gpu_pass_timer(timer); }
    ~FrameScope() { gpu::set_active_gpu_pass_timer(nullptr); }
    FrameScope(const FrameScope&) = delete;
    FrameScope& operator=(const FrameScope&) = delete;
  };
  // Collects the last frame's GPU passes, then starts frame `frame` on the GPU timer.
  [[nodiscard]] FrameScope begin_frame(uint64_t frame);
  // The frame's CPU spans from the schedule's last run.
  void end_frame(const std::vector<ecs::SystemStats>& stats, uint64_t frame);
  // Waits for the GPU to finish the passes issued so far and returns every span.
  const std::vector<TraceSpan>& trace();
  // The spans recorded since the last call, without waiting for the GPU (its passes arrive a
  // frame late), and forgets them: a viewer that profiles for hours keeps no history here.
  std::vector<TraceSpan> take_spans();

 private:
  void collect_gpu_spans();

  std::chrono::steady_clock::time_point origin_;
  std::unique_ptr<gpu::GpuPassTimer> gpu_timer_;
  std::vector<TraceSpan> trace_;
};

}  // namespace pyro
