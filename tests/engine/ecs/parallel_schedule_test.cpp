// The parallel schedule: systems of one phase that do not conflict run at the same time,
// conflicting ones never overlap and keep the sequential order, main_thread systems run on the
// calling thread, the stats say which thread ran each system, and a failure stops the frame.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"

namespace {

using pyro::ecs::Access;
using pyro::ecs::Phase;
using pyro::ecs::Reads;
using pyro::ecs::Schedule;
using pyro::ecs::SystemDesc;
using pyro::ecs::World;
using pyro::ecs::Writes;

struct A {
  int v = 0;
};
struct B {
  int v = 0;
};
struct Shared {
  int v = 0;
};

// Arrives, then waits (up to `patience`) until `count` systems have arrived: true if they did,
// which proves that they were running at the same time.
bool meet(std::atomic<int>& arrived, int count, std::chrono::milliseconds patience) {
  arrived.fetch_add(1);
  const auto until = std::chrono::steady_clock::now() + patience;
  while (arrived.load() < count)
    if (std::chrono::steady_clock::now() > until) return false;
  return true;
}

TEST(ParallelSchedule, SystemsThatDoNotConflictRunAtTheSameTime) {
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 2);
  std::atomic<int> arrived{0};
  std::atomic<int> met{0};
  Schedule s;
  s.set_threads(2);
  for (const char* name : {"left", "right"}) {
    SystemDesc d;
    d.name = name;
    d.phase = Phase::simulate;
    d.access = std::string(name) == "left" ? Access::of<Writes<A>>() : Access::of<Writes<B>>();
    d.run = [&](World&) { met += meet(arrived, 2, std::chrono::seconds(20)); };
    s.add(std::move(d));
  }
  EXPECT_TRUE(s.conflicts().empty());
  World w;
  s.run_frame(w);
  EXPECT_EQ(met.load(), 2);
  // Two threads ran them: one the caller (0), the other a worker (>= 1).
  EXPECT_NE(s.stats()[0].thread, s.stats()[1].thread);
  EXPECT_TRUE(s.stats()[0].thread >= 1 || s.stats()[1].thread >= 1);
}

TEST(ParallelSchedule, ConflictingSystemsNeverOverlapAndKeepTheirOrder) {
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  std::atomic<int> inside{0};
  std::atomic<bool> overlapped{false};
  std::mutex log_mutex;
  std::vector<std::string> log;
  Schedule s;
  s.set_threads(4);
  const auto add = [&](std::string name, Access access) {
    SystemDesc d;
    d.name = name;
    d.phase = Phase::simulate;
    d.access = std::move(access);
    d.run = [&, name](World& w) {
      if (inside.fetch_add(1) != 0) overlapped = true;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      w.resource<Shared>().v += 1;
      {
        const std::lock_guard lock(log_mutex);
        log.push_back(name);
      }
      inside.fetch_sub(1);
    };
    s.add(std::move(d));
  };
  add("first", Access::of<Writes<Shared>>());
  add("second", Access::of<Writes<Shared>>());
  add("third", Access::of<Reads<A>, Writes<Shared>>());
  World w;
  w.set_resource<Shared>();
  for (int f = 0; f < 20; ++f) s.run_frame(w);
  EXPECT_FALSE(overlapped.load());
  EXPECT_EQ(w.resource<Shared>().v, 60);
  ASSERT_EQ(log.size(), 60u);
  for (std::size_t k = 0; k < log.size(); k += 3)
    EXPECT_EQ((std::vector<std::string>{log[k], log[k + 1], log[k + 2]}),
              (std::vector<std::string>{"first", "second", "third"}));
}

TEST(ParallelSchedule, AfterOrdersSystemsThatDoNotConflict) {
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  std::atomic<int> stage{0};
  std::atomic<bool> early{false};
  Schedule s;
  s.set_threads(4);
  s.add({.name = "slow",
         .phase = Phase::render,
         .access = Access::of<Writes<A>>(),
         .run = [&](World&) {
           std::this_thread::sleep_for(std::chrono::milliseconds(5));
           stage = 1;
         }});
  s.add({.name = "later",
         .phase = Phase::render,
         .access = Access::of<Writes<B>>(),
         .run = [&](World&) { early = early || stage.load() != 1; },
         .after = {"slow"}});
  World w;
  for (int f = 0; f < 5; ++f) {
    stage = 0;
    s.run_frame(w);
  }
  EXPECT_FALSE(early.load());
}

TEST(ParallelSchedule, MainThreadSystemsRunOnTheCallingThread) {
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> wrong{0};
  Schedule s;
  s.set_threads(4);
  for (int k = 0; k < 6; ++k) {
    SystemDesc d;
    d.name = "system " + std::to_string(k);
    d.phase = k < 3 ? Phase::simulate : Phase::render;
    d.main_thread = k % 2 == 1;
    const bool main = d.main_thread;
    d.run = [&, main](World&) {
      if (main && std::this_thread::get_id() != caller) ++wrong;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    };
    s.add(std::move(d));
  }
  World w;
  for (int f = 0; f < 10; ++f) s.run_frame(w);
  EXPECT_EQ(wrong.load(), 0);
  for (const auto& st : s.stats()) {
    if (st.name == "system 1" || st.name == "system 3" || st.name == "system 5") {
      EXPECT_EQ(st.thread, 0) << st.name;
    }
  }
}

TEST(ParallelSchedule, OneThreadRunsEverythingInOrderOnTheCaller) {
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::string> log;
  bool elsewhere = false;
  Schedule s;
  s.set_threads(1);
  for (const char* name : {"a", "b", "c"})
    s.add({.name = name,
           .phase = Phase::simulate,
           .access = std::string(name) == "a" ? Access::of<Writes<A>>() : Access::of<Writes<B>>(),
           .run = [&, name](World&) {
             log.push_back(name);
             elsewhere = elsewhere || std::this_thread::get_id() != caller;
           }});
  World w;
  s.run_frame(w);
  EXPECT_EQ(log, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_FALSE(elsewhere);
  for (const auto& st : s.stats()) EXPECT_EQ(st.thread, 0);
  EXPECT_THROW(s.set_threads(-1), std::invalid_argument);
}

TEST(ParallelSchedule, AFailureStopsTheFrameAndPropagates) {
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  std::atomic<int> after_failure{0};
  Schedule s;
  s.set_threads(4);
  s.add({.name = "fails",
         .phase = Phase::simulate,
         .access = Access::of<Writes<A>>(),
         .run = [](World&) { throw std::runtime_error("broken system"); }});
  s.add({.name = "waits_for_it",
         .phase = Phase::simulate,
         .access = Access::of<Reads<A>>(),
         .run = [&](World&) { ++after_failure; }});
  s.add({.name = "next_phase", .phase = Phase::render, .run = [&](World&) { ++after_failure; }});
  World w;
  try {
    s.run_frame(w);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "broken system");
  }
  EXPECT_EQ(after_failure.load(), 0);
  EXPECT_EQ(s.stats()[0].frames, 0u);  // its timing is not recorded
}

TEST(ParallelSchedule, AccessIsCheckedOnWorkerThreadsToo) {
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  Schedule s;
  s.set_threads(4);
  for (int k = 0; k < 4; ++k)
    s.add({.name = "reader " + std::to_string(k),
           .phase = Phase::simulate,
           .access = Access::of<Reads<A>>(),
           .run = [k](World& w) {
             if (k == 3) w.resource<B>().v = 1;  // undeclared
             (void)w.resource<const A>();
           }});
  World w;
  w.set_resource<A>();
  w.set_resource<B>();
  try {
    s.run_frame(w);
    ADD_FAILURE() << "no exception";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("system 'reader 3'"), std::string::npos) << e.what();
  }
  EXPECT_EQ(w.resource<B>().v, 0);
}

}  // namespace
