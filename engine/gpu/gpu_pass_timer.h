#pragma once
// GPU time of render passes, from timer queries (ARB_timer_query, core since OpenGL 3.3):
// glQueryCounter(GL_TIMESTAMP) before and after each pass, so passes may nest; optionally the
// fragments a pass drew, from a GL_SAMPLES_PASSED occlusion query (samples that passed the
// depth test; with one sample per pixel, fragments written). Results are read only in
// collect(), which the caller runs once the GPU is past the passes (a frame later, or after
// glFinish), so timing never stalls the frame it measures. Query objects are pooled and reused.
//
// GPU timestamps are placed on the CPU's timeline with an offset measured at begin_frame():
// glGetInteger64v(GL_TIMESTAMP) against std::chrono::steady_clock::now().
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/gpu/gl_objects.h"

namespace pyro::gpu {

struct GpuPassSample {
  std::string name;
  uint64_t frame = 0;
  double start_us = 0.0;     // on the CPU timeline, microseconds after the timer's origin
  double duration_us = 0.0;  // >= 0
  int64_t fragments = -1;    // < 0: not counted
};

class GpuPassTimer {
 public:
  // `origin` is time 0 of the samples' start_us. Needs a current OpenGL context.
  explicit GpuPassTimer(std::chrono::steady_clock::time_point origin);
  GpuPassTimer(const GpuPassTimer&) = delete;
  GpuPassTimer& operator=(const GpuPassTimer&) = delete;

  // Starts frame `frame`: later passes carry its number; re-measures the clock offset.
  void begin_frame(uint64_t frame);
  // Starts a pass; returns its handle for end(). Only one pass at a time counts fragments
  // (occlusion queries cannot nest): a nested request to count is ignored.
  int begin(const std::string& name, bool count_fragments);
  void end(int pass);
  // The samples of every ended pass, in the order they began, waiting for the GPU where it
  // has not reached them yet. Their queries go back to the pool.
  std::vector<GpuPassSample> collect();

 private:
  struct Pass {
    std::string name;
    uint64_t frame = 0;
    int64_t offset_ns = 0;  // CPU ns minus GPU ns when the pass began
    Query begin, end, samples;
    bool ended = false;
  };
  Query take(std::vector<Query>& pool, GLenum target);

  std::chrono::steady_clock::time_point origin_;
  uint64_t frame_ = 0;
  int64_t offset_ns_ = 0;
  bool counting_ = false;
  std::vector<Pass> passes_;
  std::vector<Query> free_timestamps_, free_samples_;
};

// The timer that render passes report to; null (the default) when nobody is profiling.
GpuPassTimer* active_gpu_pass_timer();
void set_active_gpu_pass_timer(GpuPassTimer* timer);

// Times the GL commands issued during its lifetime as one pass of the active timer (nothing
// when there is none). For a render system's inner passes: `GpuPassScope p("fire layer", true);`
class GpuPassScope {
 public:
  // `name` is copied only when a timer is active (no allocation when nobody profiles).
  explicit GpuPassScope(const char* name, bool count_fragments = false);
  ~GpuPassScope();
  GpuPassScope(const GpuPassScope&) = delete;
  GpuPassScope& operator=(const GpuPassScope&) = delete;

 private:
  GpuPassTimer* timer_;
  int pass_ = -1;
};

}  // namespace pyro::gpu
