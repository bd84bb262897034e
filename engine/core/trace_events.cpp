#include "engine/core/trace_events.h"

#include <nlohmann/json.hpp>
#include <set>

namespace pyro {

int trace_tid(const TraceSpan& span) {
  if (span.track == TraceTrack::gpu) return int(TraceTrack::gpu);
  return span.thread > 0 ? int(TraceTrack::gpu) + span.thread : int(TraceTrack::cpu);
}

std::string chrome_trace_json(const std::vector<TraceSpan>& spans, const std::string& process_name) {
  using json = nlohmann::json;
  const auto thread_name = [](int tid, const std::string& name) {
    return json{
        {"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", tid}, {"args", {{"name", name}}}};
  };
  json events = json::array();
  events.push_back({{"name", "process_name"}, {"ph", "M"}, {"pid", 1}, {"tid", 0},
                    {"args", {{"name", process_name}}}});
  events.push_back(thread_name(int(TraceTrack::cpu), "CPU: frame thread (systems)"));
  events.push_back(thread_name(int(TraceTrack::gpu), "GPU: passes (timer queries)"));
  std::set<int> workers;
  for (const TraceSpan& s : spans)
    if (s.track == TraceTrack::cpu && s.thread > 0) workers.insert(s.thread);
  for (const int k : workers)
    events.push_back(thread_name(int(TraceTrack::gpu) + k, "CPU: worker " + std::to_string(k)));
  for (const TraceSpan& s : spans) {
    json args = {{"frame", s.frame}};
    if (s.fragments >= 0) args["fragments"] = s.fragments;
    events.push_back({{"name", s.name},
                      {"cat", s.category},
                      {"ph", "X"},
                      {"pid", 1},
                      {"tid", trace_tid(s)},
                      {"ts", s.start_us},
                      {"dur", s.duration_us},
                      {"args", args}});
  }
  return json{{"traceEvents", events}, {"displayTimeUnit", "ms"}}.dump(1) + "\n";
}

}  // namespace pyro
