#include "engine/ecs/schedule.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace pyro::ecs {

const char* phase_name(Phase phase) {
  switch (phase) {
    case Phase::spawn:
      return "spawn";
    case Phase::simulate:
      return "simulate";
    case Phase::sort:
      return "sort";
    case Phase::camera:
      return "camera";
    case Phase::render:
      return "render";
    case Phase::composite:
      return "composite";
    case Phase::output:
      return "output";
  }
  return "unknown";
}

void Schedule::add(SystemDesc system) {
  if (system.name.empty()) throw std::invalid_argument("Schedule::add: a system needs a name");
  if (!system.run)
    throw std::invalid_argument("Schedule::add: system '" + system.name + "' has no run function");
  for (const SystemDesc& s : systems_)
    if (s.name == system.name)
      throw std::invalid_argument("Schedule::add: a system named '" + system.name +
                                  "' is already scheduled");

  // After the last system of the same or an earlier phase: phases in order, FIFO within.
  const auto at =
      std::upper_bound(systems_.begin(), systems_.end(), system.phase,
                       [](Phase p, const SystemDesc& s) { return int(p) < int(s.phase); });
  const auto offset = at - systems_.begin();

  SystemStats st;
  st.name = system.name;
  st.phase = system.phase;
  st.reads = system.reads;
  st.writes = system.writes;
  systems_.insert(at, std::move(system));
  try {
    stats_.insert(stats_.begin() + offset, std::move(st));
  } catch (...) {
    systems_.erase(systems_.begin() + offset);  // keep the two vectors parallel
    throw;
  }
}

void Schedule::run_frame(World& world) {
  run_phases_through(world, all_phases[std::size(all_phases) - 1]);
  ++frames_;
}

void Schedule::run_phases_through(World& world, Phase last) {
  run_phases(world, all_phases[0], last);
}

void Schedule::run_phases(World& world, Phase first, Phase last) {
  using clock = std::chrono::steady_clock;
  for (std::size_t i = 0; i < systems_.size(); ++i) {
    if (systems_[i].phase < first) continue;
    if (systems_[i].phase > last) break;  // systems_ is sorted by phase
    const auto t0 = clock::now();
    systems_[i].run(world);
    const double ms = std::chrono::duration<double, std::milli>(clock::now() - t0).count();
    SystemStats& st = stats_[i];
    st.last_ms = ms;
    st.last_start = t0;
    st.total_ms += ms;
    st.max_ms = std::max(st.max_ms, ms);
    ++st.frames;
  }
}

std::vector<std::string> Schedule::order() const {
  std::vector<std::string> names;
  names.reserve(systems_.size());
  for (const SystemDesc& s : systems_) names.push_back(s.name);
  return names;
}

namespace {
bool intersects(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  for (const std::string& x : a)
    if (std::find(b.begin(), b.end(), x) != b.end()) return true;
  return false;
}
}  // namespace

std::vector<std::pair<std::string, std::string>> Schedule::conflicts() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t i = 0; i < systems_.size(); ++i) {
    for (std::size_t j = i + 1; j < systems_.size() && systems_[j].phase == systems_[i].phase;
         ++j) {
      const SystemDesc& a = systems_[i];
      const SystemDesc& b = systems_[j];
      if (intersects(a.writes, b.reads) || intersects(a.writes, b.writes) ||
          intersects(b.writes, a.reads))
        out.emplace_back(a.name, b.name);
    }
  }
  return out;
}

}  // namespace pyro::ecs
