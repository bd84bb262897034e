#include "engine/ecs/schedule.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "engine/ecs/world.h"

namespace pyro::ecs {

const char* phase_name(Phase phase) {
  switch (phase) {
    case Phase::spawn:
      return "spawn";
    case Phase::simulate:
      return "simulate";
    case Phase::camera:
      return "camera";
    case Phase::sort:
      return "sort";
    case Phase::render:
      return "render";
    case Phase::composite:
      return "composite";
    case Phase::output:
      return "output";
  }
  return "unknown";
}

void run_system_once(const SystemDesc& system, World& world) {
  if (!system.run)
    throw std::invalid_argument("run_system_once: system '" + system.name + "' has no run function");
  world.reserve_type_slots(std::max(system.access.type_slots(), type_id<Entities>() + 1));
  const RunningSystem running{&system.name, &system.access};
  const RunningSystemScope scope(running);
  if (system.setup) system.setup(world);
  system.run(world);
}

std::size_t Schedule::index_of(const std::string& name) const {
  for (std::size_t i = 0; i < systems_.size(); ++i)
    if (systems_[i].name == name) return i;
  return systems_.size();
}

void Schedule::add(SystemDesc system) {
  if (system.name.empty()) throw std::invalid_argument("Schedule::add: a system needs a name");
  if (!system.run)
    throw std::invalid_argument("Schedule::add: system '" + system.name + "' has no run function");
  if (index_of(system.name) != systems_.size())
    throw std::invalid_argument("Schedule::add: a system named '" + system.name +
                                "' is already scheduled");
  for (const std::string& before : system.after) {
    const std::size_t b = index_of(before);
    if (b == systems_.size())
      throw std::invalid_argument("Schedule::add: system '" + system.name + "' runs after '" +
                                  before + "', which is not scheduled (add it first)");
    if (systems_[b].phase > system.phase)
      throw std::invalid_argument("Schedule::add: system '" + system.name + "' (phase " +
                                  phase_name(system.phase) + ") cannot run after '" + before +
                                  "' (phase " + phase_name(systems_[b].phase) + ")");
  }

  // After the last system of the same or an earlier phase: phases in order, FIFO within. An
  // `after` names a system already added, so insertion order respects it.
  const auto at =
      std::upper_bound(systems_.begin(), systems_.end(), system.phase,
                       [](Phase p, const SystemDesc& s) { return int(p) < int(s.phase); });
  const auto offset = at - systems_.begin();

  SystemStats st;
  st.name = system.name;
  st.phase = system.phase;
  type_slots_ = std::max(type_slots_, system.access.type_slots());
  type_slots_ = std::max(type_slots_, type_id<Entities>() + 1);
  systems_.insert(at, std::move(system));
  try {
    stats_.insert(stats_.begin() + offset, std::move(st));
  } catch (...) {
    systems_.erase(systems_.begin() + offset);  // keep the two vectors parallel
    throw;
  }
  // The running-system records point into systems_, which just moved.
  running_.clear();
  for (const SystemDesc& s : systems_) running_.push_back({&s.name, &s.access});
}

void Schedule::setup(World& world) {
  world.reserve_type_slots(type_slots_);
  for (std::size_t i = 0; i < systems_.size(); ++i) {
    if (!systems_[i].setup) continue;
    const RunningSystemScope scope(running_[i]);
    systems_[i].setup(world);
  }
}

void Schedule::run_frame(World& world) {
  run_phases_through(world, all_phases[std::size(all_phases) - 1]);
  ++frames_;
}

void Schedule::run_phases_through(World& world, Phase last) {
  run_phases(world, all_phases[0], last);
}

void Schedule::run_system(World& world, std::size_t i) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  {
    const RunningSystemScope scope(running_[i]);
    systems_[i].run(world);
  }
  const double ms = std::chrono::duration<double, std::milli>(clock::now() - t0).count();
  SystemStats& st = stats_[i];
  st.last_ms = ms;
  st.last_start = t0;
  st.total_ms += ms;
  st.max_ms = std::max(st.max_ms, ms);
  st.thread = 0;
  ++st.frames;
}

void Schedule::run_phases(World& world, Phase first, Phase last) {
  world.reserve_type_slots(type_slots_);
  for (std::size_t i = 0; i < systems_.size(); ++i) {
    if (systems_[i].phase < first) continue;
    if (systems_[i].phase > last) break;  // systems_ is sorted by phase
    run_system(world, i);
  }
}

std::vector<std::string> Schedule::order() const {
  std::vector<std::string> names;
  names.reserve(systems_.size());
  for (const SystemDesc& s : systems_) names.push_back(s.name);
  return names;
}

bool Schedule::ordered(const std::string& earlier, const std::string& later) const {
  // Depth-first through the `after` lists, which only point backwards in run order.
  std::vector<std::size_t> todo{index_of(later)};
  std::vector<bool> seen(systems_.size(), false);
  while (!todo.empty()) {
    const std::size_t i = todo.back();
    todo.pop_back();
    if (i >= systems_.size() || seen[i]) continue;
    seen[i] = true;
    for (const std::string& before : systems_[i].after) {
      if (before == earlier) return true;
      todo.push_back(index_of(before));
    }
  }
  return false;
}

std::vector<std::pair<std::string, std::string>> Schedule::conflicts() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t i = 0; i < systems_.size(); ++i) {
    for (std::size_t j = i + 1; j < systems_.size() && systems_[j].phase == systems_[i].phase;
         ++j) {
      if (systems_[i].access.conflicts_with(systems_[j].access))
        out.emplace_back(systems_[i].name, systems_[j].name);
    }
  }
  return out;
}

std::vector<std::pair<std::string, std::string>> Schedule::unordered_conflicts() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (auto& [a, b] : conflicts())
    if (!ordered(a, b)) out.emplace_back(a, b);
  return out;
}

}  // namespace pyro::ecs
