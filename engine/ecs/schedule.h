#pragma once
// The frame schedule: systems run phase by phase in a fixed order, and in insertion order
// within a phase. Every run is timed. Each system declares by type what it reads and writes
// (engine/ecs/access.h); while it runs, the World refuses any access it did not declare. Two
// systems of one phase conflict when one writes what the other reads or writes; a conflicting
// pair should be ordered explicitly (SystemDesc::after), and unordered_conflicts() lists the
// pairs that are not.
//
// Parallel execution (set_threads): within a phase, a system starts once every earlier system
// of the phase that it conflicts with or names in `after` has finished; systems with no such
// tie run concurrently on TBB worker threads, while main_thread systems run on the thread that
// called run_frame. Phases still run one after another. The order of conflicting systems is the
// sequential run order, so results do not depend on the thread count.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/ecs/access.h"

namespace pyro::ecs {

class World;

// The order data flows through a frame: particles are spawned and simulated, the lights are
// gathered and what the renderers need of them is made in light space (once per frame, whatever
// the number of eyes), the camera makes this frame's eye frames, the sort orders particles for
// those eyes, the renderers draw them, the views are composited into the output image, and the
// output is read back.
enum class Phase { spawn, simulate, light, camera, sort, render, composite, output };

inline constexpr Phase all_phases[] = {Phase::spawn,  Phase::simulate, Phase::light,
                                       Phase::camera, Phase::sort,     Phase::render,
                                       Phase::composite, Phase::output};

const char* phase_name(Phase phase);

// Members have default initialisers, so designated initialisers may leave any of them out.
struct SystemDesc {
  std::string name{};
  Phase phase = Phase::simulate;
  // Every component and resource type the system touches, read or written.
  Access access{};
  std::function<void(World&)> run{};
  // Optional, run once by Schedule::setup when the world is built, before the first frame:
  // creates the resources the system writes (renderers, scratch space, outputs), so that
  // nothing is created lazily while frames run. Checked against `access` like run.
  std::function<void(World&)> setup{};
  // Systems, already added, of the same or an earlier phase, that must finish before this one
  // starts (an explicit order for a conflicting pair).
  std::vector<std::string> after{};
  // The system issues GL calls, so it must run on the thread that owns the GL context: the
  // thread that calls run_frame.
  bool main_thread = false;
};

struct SystemStats {
  std::string name;
  Phase phase = Phase::simulate;
  double last_ms = 0;
  // When the last run began (steady clock): profilers place the run on a timeline with it.
  std::chrono::steady_clock::time_point last_start{};
  double total_ms = 0;
  double max_ms = 0;
  uint64_t frames = 0;
  // The thread of the last run: 0 the thread that called run_frame, k >= 1 the k-th worker
  // thread (numbered by first use, process-wide), so traces show one track per thread.
  int thread = 0;

  double mean_ms() const { return frames ? total_ms / double(frames) : 0.0; }
};

// Runs one system alone on `world` as a schedule would: its setup, then its run, each under
// its declared access (for tests and tools that exercise a system on a hand-built world).
void run_system_once(const SystemDesc& system, World& world);

class Schedule {
 public:
  Schedule();
  ~Schedule();
  Schedule(Schedule&&) noexcept;
  Schedule& operator=(Schedule&&) noexcept;

  // How many threads run the systems: 1 runs them one by one in order() on the calling thread
  // (the sequential schedule); n > 1 lets at most n threads (the caller included) run the
  // systems of a phase that do not conflict, and the particle loops inside them; 0 (the
  // default) is TBB's default, one per core. Throws std::invalid_argument below 0.
  void set_threads(int threads);
  int threads() const { return threads_; }
  // The number of threads that threads() stands for (TBB's default concurrency for 0).
  int effective_threads() const;

  // Throws std::invalid_argument for an empty or duplicate name, an empty run function, or an
  // `after` naming a system that is not yet added or that runs in a later phase.
  void add(SystemDesc system);

  // Runs every system's setup once, in order(), each under its declared access.
  void setup(World& world);

  // Runs every system once, in order() (or concurrently where set_threads allows), timing each.
  // An exception from a system propagates; the systems after it do not run (in parallel: none
  // starts after it; those already running finish) and its own timing is not recorded.
  void run_frame(World& world);

  // Runs, in order(), only the systems whose phase is `last` or earlier (e.g. Phase::simulate:
  // advance the simulation without sorting or rendering), timing each like run_frame.
  void run_phases_through(World& world, Phase last);

  // Runs, in order(), only the systems whose phase lies in [first, last] (e.g. Phase::light to
  // Phase::output: draw the current state again without advancing the simulation, as the
  // viewer does while paused), timing each like run_frame.
  void run_phases(World& world, Phase first, Phase last);

  // One entry per system, in run order.
  const std::vector<SystemStats>& stats() const { return stats_; }
  // The systems as added, in run order.
  const std::vector<SystemDesc>& systems() const { return systems_; }

  // System names in run order.
  std::vector<std::string> order() const;

  // Pairs (earlier, later in run order) of systems in the same phase where one writes
  // something the other reads or writes.
  std::vector<std::pair<std::string, std::string>> conflicts() const;
  // The conflicting pairs that no chain of `after` orders.
  std::vector<std::pair<std::string, std::string>> unordered_conflicts() const;
  // True when system `later` runs after `earlier` through a chain of `after` declarations.
  bool ordered(const std::string& earlier, const std::string& later) const;

  std::size_t size() const { return systems_.size(); }
  uint64_t frames() const { return frames_; }

 private:
  struct Executor;  // the TBB arena and the phases' dependency lists (schedule.cpp)

  std::size_t index_of(const std::string& name) const;
  void run_system(World& world, std::size_t i, int thread);
  void run_sequential(World& world, Phase first, Phase last);
  void run_parallel(World& world, Phase first, Phase last);

  // Kept sorted by phase (stable, so insertion order holds within a phase); stats_ and
  // running_ are parallel to it.
  std::vector<SystemDesc> systems_;
  std::vector<SystemStats> stats_;
  std::vector<RunningSystem> running_;
  std::size_t type_slots_ = 0;  // World::reserve_type_slots before running
  uint64_t frames_ = 0;
  int threads_ = 0;
  std::unique_ptr<Executor> executor_;  // made on the first parallel run after a change
};

}  // namespace pyro::ecs
