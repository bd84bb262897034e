#pragma once
// A profiling run's spans and their Chrome trace-event form (the JSON that chrome://tracing
// and Perfetto open): one "complete" event ("ph": "X") per span, times in microseconds, one
// thread (track) per timeline: the CPU systems on one, the GPU passes on another.
// Format: "Trace Event Format", Google, 2016 (docs.google.com/document/d/1CvAClvFfyA5R-PhYUmn5OOQtYMH4h6I0nSsKchNAySU).
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
};

// {"traceEvents": [...], "displayTimeUnit": "ms", "otherData": {...}}: a thread-name
// metadata event per track, then the spans in order. `process_name` names pid 1.
std::string chrome_trace_json(const std::vector<TraceSpan>& spans, const std::string& process_name);

}  // namespace pyro
