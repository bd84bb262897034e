#include "engine/core/trace_events.h"

#include <nlohmann/json.hpp>

namespace pyro {

std::string chrome_trace_json(const std::vector<TraceSpan>& spans, const std::string& process_name) {
  using json = nlohmann::json;
  json events = json::array();
  events.push_back({{"name", "process_name"}, {"ph", "M"}, {"pid", 1}, {"tid", 0},
                    {"args", {{"name", process_name}}}});
  events.push_back({{"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", int(TraceTrack::cpu)},
                    {"args", {{"name", "CPU: systems"}}}});
  events.push_back({{"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", int(TraceTrack::gpu)},
                    {"args", {{"name", "GPU: passes (timer queries)"}}}});
  for (const TraceSpan& s : spans) {
    json args = {{"frame", s.frame}};
    if (s.fragments >= 0) args["fragments"] = s.fragments;
    events.push_back({{"name", s.name},
                      {"cat", s.category},
                      {"ph", "X"},
                      {"pid", 1},
                      {"tid", int(s.track)},
                      {"ts", s.start_us},
                      {"dur", s.duration_us},
                      {"args", args}});
  }
  return json{{"traceEvents", events}, {"displayTimeUnit", "ms"}}.dump(1) + "\n";
}

}  // namespace pyro
