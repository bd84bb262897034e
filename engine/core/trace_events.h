#pragma once
// A profiling run's spans and their Chrome trace-event form (the JSON that chrome://tracing
// and Perfetto open): one "complete" event ("ph": "X") per span, times in microseconds, one
// thread (track, "tid") per timeline: tid 1 the CPU thread that runs the frame (the frame spans
// and the systems it ran), tid 2 the GPU passes, tid 2 + k the k-th worker thread of the
// parallel schedule (the systems it ran).
// Format: "Trace Event Format", Google, 2016
// (docs.google.com/document/d/1CvAClvFfyA5R-PhYUmn5OOQtYMH4h6I0nSsKchNAySU).
#include <cstdint>
#include <string>
#include <vector>

namespace pyro {

enum class TraceTrack : int { cpu = 1, gpu = 2 };

struct TraceSpan {
  std::string name;      // system or pass, e.g. "billboard_render"
  std::string category;  // "frame", the system's phase, or "gpu"
  TraceTrack track = TraceTrack::cpu;
  double start_us = 0.0;     // on the run's timeline (0 = when profiling began)
  double duration_us = 0.0;  // >= 0
  uint64_t frame = 0;
  // Fragments that passed the depth test in this pass (GL_SAMPLES_PASSED); < 0 when not counted.
  int64_t fragments = -1;
  // CPU spans: 0 the thread that ran the frame, k >= 1 the schedule's k-th worker thread
  // (ecs::SystemStats::thread).
  int thread = 0;
};

// The Chrome "tid" of a span: 1 or 2 for the CPU and GPU tracks, 2 + thread for a worker.
int trace_tid(const TraceSpan& span);

// {"traceEvents": [...], "displayTimeUnit": "ms", "otherData": {...}}: a thread-name
// metadata event per track (per worker thread that ran a span), then the spans in order.
// `process_name` names pid 1.
std::string chrome_trace_json(const std::vector<TraceSpan>& spans, const std::string& process_name);

}  // namespace pyro
