#pragma once
// The frame schedule: systems run phase by phase in a fixed order, and in insertion order
// within a phase. Every run is timed, and each system declares what it reads and writes so
// that conflicts (two systems of one phase touching the same data, one of them writing) can
// be reported today and used to decide what may run in parallel later.
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "engine/ecs/component_pool.h"

namespace pyro::ecs {

class World;

enum class Phase { spawn, simulate, sort, camera, render, composite, output };

inline constexpr Phase all_phases[] = {Phase::spawn,  Phase::simulate,  Phase::sort,  Phase::camera,
                                       Phase::render, Phase::composite, Phase::output};

const char* phase_name(Phase phase);

struct SystemDesc {
  std::string name;
  Phase phase = Phase::simulate;
  std::vector<std::string> reads;
  std::vector<std::string> writes;
  std::function<void(World&)> run;
};

// Names of component or resource types, for SystemDesc::reads / writes:
//   .reads = access<Position, Velocity>(), .writes = access<Position>()
template <class... Ts>
std::vector<std::string> access() {
  return {type_name<Ts>()...};
}

struct SystemStats {
  std::string name;
  Phase phase = Phase::simulate;
  double last_ms = 0;
  // When the last run began (steady clock): profilers place the run on a timeline with it.
  std::chrono::steady_clock::time_point last_start{};
  double total_ms = 0;
  double max_ms = 0;
  uint64_t frames = 0;
  std::vector<std::string> reads, writes;

  double mean_ms() const { return frames ? total_ms / double(frames) : 0.0; }
};

class Schedule {
 public:
  // Throws std::invalid_argument for an empty or duplicate name or an empty run function.
  void add(SystemDesc system);

  // Runs every system once, in order(), timing each. An exception from a system propagates;
  // the systems after it do not run and its own timing is not recorded.
  void run_frame(World& world);

  // Runs, in order(), only the systems whose phase is `last` or earlier (e.g. Phase::simulate:
  // advance the simulation without sorting or rendering), timing each like run_frame.
  void run_phases_through(World& world, Phase last);

  // Runs, in order(), only the systems whose phase lies in [first, last] (e.g. Phase::sort to
  // Phase::output: draw the current state again without advancing the simulation, as the
  // viewer does while paused), timing each like run_frame.
  void run_phases(World& world, Phase first, Phase last);

  // One entry per system, in run order.
  const std::vector<SystemStats>& stats() const { return stats_; }

  // System names in run order.
  std::vector<std::string> order() const;

  // Pairs (earlier, later in run order) of systems in the same phase where one writes
  // something the other reads or writes.
  std::vector<std::pair<std::string, std::string>> conflicts() const;

  std::size_t size() const { return systems_.size(); }
  uint64_t frames() const { return frames_; }

 private:
  // Kept sorted by phase (stable, so insertion order holds within a phase); stats_ is
  // parallel to it.
  std::vector<SystemDesc> systems_;
  std::vector<SystemStats> stats_;
  uint64_t frames_ = 0;
};

}  // namespace pyro::ecs
