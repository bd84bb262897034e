// Chrome trace events: one track (tid) per timeline, a worker thread's spans on a track of its
// own, every used track named by a metadata event.
#include "engine/core/trace_events.h"

#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace pyro {
namespace {

TEST(TraceEvents, OneTrackPerThreadAndEveryTrackNamed) {
  std::vector<TraceSpan> spans = {
      {"frame 0", "frame", TraceTrack::cpu, 0.0, 100.0, 0, -1, 0},
      {"animation", "simulate", TraceTrack::cpu, 1.0, 10.0, 0, -1, 2},
      {"camera_orbit", "simulate", TraceTrack::cpu, 1.0, 5.0, 0, -1, 0},
      {"sorting", "sort", TraceTrack::cpu, 12.0, 8.0, 0, -1, 1},
      {"billboard_render", "gpu", TraceTrack::gpu, 30.0, 40.0, 0, 1234, 0},
  };
  const nlohmann::json trace = nlohmann::json::parse(chrome_trace_json(spans, "pyro test"));
  std::map<int, std::string> names;
  std::map<std::string, int> tid_of;
  for (const auto& e : trace["traceEvents"]) {
    if (e["ph"] == "M") {
      if (e["name"] == "thread_name") names[e["tid"]] = e["args"]["name"];
      continue;
    }
    tid_of[e["name"]] = e["tid"];
  }
  EXPECT_EQ(tid_of["frame 0"], 1);
  EXPECT_EQ(tid_of["camera_orbit"], 1);      // the frame's thread
  EXPECT_EQ(tid_of["billboard_render"], 2);  // the GPU track
  EXPECT_EQ(tid_of["sorting"], 3);           // worker 1
  EXPECT_EQ(tid_of["animation"], 4);         // worker 2
  ASSERT_EQ(names.size(), 4u);
  EXPECT_EQ(names[3], "CPU: worker 1");
  EXPECT_EQ(names[4], "CPU: worker 2");
  EXPECT_EQ(trace_tid(spans[4]), 2);
}

}  // namespace
}  // namespace pyro
