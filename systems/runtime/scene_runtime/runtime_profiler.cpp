#include "systems/runtime/scene_runtime/runtime_profiler.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>

namespace pyro {

RuntimeProfiler::RuntimeProfiler()
    : origin_(std::chrono::steady_clock::now()),
      gpu_timer_(std::make_unique<gpu::GpuPassTimer>(origin_)) {}

RuntimeProfiler::FrameScope RuntimeProfiler::begin_frame(uint64_t frame) {
  collect_gpu_spans();
  gpu_timer_->begin_frame(frame);
  return FrameScope(gpu_timer_.get());
}

void RuntimeProfiler::end_frame(const std::vector<ecs::SystemStats>& stats, uint64_t f) {
  const auto us = [&](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::micro>(t - origin_).count();
  };
  if (stats.empty()) return;
  // Systems of a phase may run concurrently: the frame spans from the earliest start.
  double frame_start = us(stats.front().last_start);
  for (const ecs::SystemStats& s : stats) frame_start = std::min(frame_start, us(s.last_start));
  double frame_end = frame_start;
  const size_t first = trace_.size();
  trace_.push_back({"frame " + std::to_string(f), "frame", TraceTrack::cpu, frame_start, 0.0, f, -1});
  for (const ecs::SystemStats& s : stats) {
    const double start = us(s.last_start);
    trace_.push_back({s.name, ecs::phase_name(s.phase), TraceTrack::cpu, start, s.last_ms * 1e3, f,
                      -1, s.thread});
    frame_end = std::max(frame_end, start + s.last_ms * 1e3);
  }
  trace_[first].duration_us = frame_end - frame_start;
}

void RuntimeProfiler::collect_gpu_spans() {
  for (gpu::GpuPassSample& s : gpu_timer_->collect())
    trace_.push_back({std::move(s.name), "gpu", TraceTrack::gpu, s.start_us, s.duration_us, s.frame,
                      s.fragments});
}

std::vector<TraceSpan> RuntimeProfiler::take_spans() {
  collect_gpu_spans();
  std::vector<TraceSpan> spans = std::move(trace_);
  trace_.clear();
  return spans;
}

const std::vector<TraceSpan>& RuntimeProfiler::trace() {
  glFinish();
  collect_gpu_spans();
  return trace_;
}

}  // namespace pyro
