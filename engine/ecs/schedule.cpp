#include "engine/ecs/schedule.h"

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "engine/ecs/world.h"

namespace pyro::ecs {

namespace {

// Worker threads numbered 1, 2, ... by the first system each runs, process-wide and for the
// thread's lifetime, so a trace shows one track per thread.
int worker_number() {
  static std::atomic<int> next{1};
  thread_local const int number = next.fetch_add(1, std::memory_order_relaxed);
  return number;
}

int thread_of(std::thread::id caller) {
  return std::this_thread::get_id() == caller ? 0 : worker_number();
}

}  // namespace

// The arena the systems run in (its concurrency is the schedule's thread count) and, per
// system, the later systems of its phase that wait for it and how many earlier ones it waits
// for: those it names in `after` and those it conflicts with.
struct Schedule::Executor {
  Executor(const Schedule& s, int threads)
      : arena(threads > 0 ? threads : tbb::task_arena::automatic, 1),
        successors(s.systems_.size()),
        predecessors(s.systems_.size(), 0) {
    // systems_ is sorted by phase: the later systems of i's phase follow it.
    for (std::size_t i = 0; i < s.systems_.size(); ++i)
      for (std::size_t j = i + 1; j < s.systems_.size() && s.systems_[j].phase == s.systems_[i].phase;
           ++j) {
        const std::vector<std::string>& after = s.systems_[j].after;
        const bool named = std::find(after.begin(), after.end(), s.systems_[i].name) != after.end();
        if (!named && !s.systems_[i].access.conflicts_with(s.systems_[j].access)) continue;
        successors[i].push_back(j);
        ++predecessors[j];
      }
  }

  tbb::task_arena arena;
  std::vector<std::vector<std::size_t>> successors;
  std::vector<int> predecessors;
};

namespace {

// One phase's systems [first, first + count) run as their dependencies allow: the others on
// TBB workers (tasks of one group), main_thread systems on the calling thread, which otherwise
// waits. A failure stops systems from starting; the first exception is rethrown at the end.
template <class RunSystem>
class PhaseRun {
 public:
  PhaseRun(const std::vector<SystemDesc>& systems,
           const std::vector<std::vector<std::size_t>>& successors,
           const std::vector<int>& predecessors, std::size_t first, std::size_t count,
           RunSystem run)
      : systems_(systems),
        successors_(successors),
        first_(first),
        count_(count),
        run_(std::move(run)),
        waiting_(std::make_unique<std::atomic<int>[]>(count)) {
    for (std::size_t k = 0; k < count; ++k) waiting_[k].store(predecessors[first + k]);
  }

  void run() {
    bool on_caller = false;
    for (std::size_t k = 0; k < count_; ++k)
      on_caller = on_caller || systems_[first_ + k].main_thread;
    // The roots, found before any is launched: once systems run, counters reach 0 as their
    // predecessors finish, and those systems are launched by the predecessors.
    std::vector<std::size_t> roots;
    for (std::size_t k = 0; k < count_; ++k)
      if (waiting_[k].load() == 0) roots.push_back(first_ + k);
    for (const std::size_t i : roots) launch(i);
    if (on_caller) serve_caller();
    group_.wait();  // with no main_thread system, the caller works through the tasks here
    if (error_) std::rethrow_exception(error_);
  }

 private:
  void launch(std::size_t i) {
    if (systems_[i].main_thread) {
      {
        const std::lock_guard lock(mutex_);
        ready_on_caller_.push_back(i);
      }
      wake_.notify_one();
      return;
    }
    group_.run([this, i] { execute(i); });
  }

  void execute(std::size_t i) {
    if (!failed_.load()) {
      try {
        // Isolated: while the system waits inside its own parallel loops, its thread takes only
        // that loop's work, never another system (which would count into this one's time).
        tbb::this_task_arena::isolate([&] { run_(i); });
      } catch (...) {
        const std::lock_guard lock(mutex_);
        if (!error_) error_ = std::current_exception();
        failed_.store(true);
      }
    }
    for (const std::size_t next : successors_[i])
      if (waiting_[next - first_].fetch_sub(1) == 1) launch(next);
    {
      const std::lock_guard lock(mutex_);
      ++done_;
    }
    wake_.notify_one();
  }

  // The calling thread runs the main_thread systems as they become ready, lowest index (the
  // sequential order) first, until every system of the phase is done.
  void serve_caller() {
    std::unique_lock lock(mutex_);
    while (done_ < count_) {
      wake_.wait(lock, [&] { return !ready_on_caller_.empty() || done_ == count_; });
      while (!ready_on_caller_.empty()) {
        const auto next = std::min_element(ready_on_caller_.begin(), ready_on_caller_.end());
        const std::size_t i = *next;
        ready_on_caller_.erase(next);
        lock.unlock();
        execute(i);
        lock.lock();
      }
    }
  }

  const std::vector<SystemDesc>& systems_;
  const std::vector<std::vector<std::size_t>>& successors_;
  const std::size_t first_, count_;
  RunSystem run_;
  std::unique_ptr<std::atomic<int>[]> waiting_;
  tbb::task_group group_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<std::size_t> ready_on_caller_;
  std::size_t done_ = 0;
  std::atomic<bool> failed_{false};
  std::exception_ptr error_;
};

}  // namespace

Schedule::Schedule() = default;
Schedule::~Schedule() = default;
Schedule::Schedule(Schedule&&) noexcept = default;
Schedule& Schedule::operator=(Schedule&&) noexcept = default;

int Schedule::effective_threads() const {
  return threads_ > 0 ? threads_ : tbb::info::default_concurrency();
}

void Schedule::set_threads(int threads) {
  if (threads < 0)
    throw std::invalid_argument("Schedule::set_threads: " + std::to_string(threads) +
                                " threads (expected 0 for the default, or at least 1)");
  threads_ = threads;
  executor_.reset();
}

const char* phase_name(Phase phase) {
  switch (phase) {
    case Phase::spawn:
      return "spawn";
    case Phase::simulate:
      return "simulate";
    case Phase::light:
      return "light";
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
  const RunningSystem running(system.name, system.access);
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
  for (const SystemDesc& s : systems_) running_.emplace_back(s.name, s.access);
  executor_.reset();
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

void Schedule::run_system(World& world, std::size_t i, int thread) {
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
  st.thread = thread;
  ++st.frames;
}

void Schedule::run_phases(World& world, Phase first, Phase last) {
  world.reserve_type_slots(type_slots_);
  if (!executor_) executor_ = std::make_unique<Executor>(*this, threads_);
  // In the arena, so that the systems' own parallel loops use at most threads_ threads too.
  executor_->arena.execute([&] {
    if (threads_ == 1)
      run_sequential(world, first, last);
    else
      run_parallel(world, first, last);
  });
}

void Schedule::run_sequential(World& world, Phase first, Phase last) {
  for (std::size_t i = 0; i < systems_.size(); ++i) {
    if (systems_[i].phase < first) continue;
    if (systems_[i].phase > last) break;  // systems_ is sorted by phase
    run_system(world, i, 0);
  }
}

void Schedule::run_parallel(World& world, Phase first, Phase last) {
  const std::thread::id caller = std::this_thread::get_id();
  const auto run = [this, &world, caller](std::size_t i) {
    run_system(world, i, thread_of(caller));
  };
  for (std::size_t b = 0, e = 0; b < systems_.size(); b = e) {
    for (e = b; e < systems_.size() && systems_[e].phase == systems_[b].phase;) ++e;
    if (systems_[b].phase < first || systems_[b].phase > last) continue;
    PhaseRun phase(systems_, executor_->successors, executor_->predecessors, b, e - b, run);
    phase.run();
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
