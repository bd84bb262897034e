#include "engine/ecs/schedule.h"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "engine/ecs/world.h"

namespace {

using pyro::ecs::Access;
using pyro::ecs::Phase;
using pyro::ecs::Reads;
using pyro::ecs::Schedule;
using pyro::ecs::SystemDesc;
using pyro::ecs::World;
using pyro::ecs::Writes;

struct SchedulePosition {
  float x = 0;
};
struct ScheduleVelocity {
  float x = 0;
};
struct Image {
  int w = 0;
};

// A system that appends its name to a shared log, so the run order is observable.
SystemDesc logger(std::string name, Phase phase, std::vector<std::string>* log, Access access = {},
                  std::vector<std::string> after = {}) {
  SystemDesc s;
  s.name = name;
  s.phase = phase;
  s.access = std::move(access);
  s.run = [log, name](World&) { log->push_back(name); };
  s.after = std::move(after);
  return s;
}

TEST(Schedule, PhaseNames) {
  EXPECT_STREQ(pyro::ecs::phase_name(Phase::spawn), "spawn");
  EXPECT_STREQ(pyro::ecs::phase_name(Phase::simulate), "simulate");
  EXPECT_STREQ(pyro::ecs::phase_name(Phase::light), "light");
  EXPECT_STREQ(pyro::ecs::phase_name(Phase::sort), "sort");
  EXPECT_STREQ(pyro::ecs::phase_name(Phase::camera), "camera");
  EXPECT_STREQ(pyro::ecs::phase_name(Phase::render), "render");
  EXPECT_STREQ(pyro::ecs::phase_name(Phase::composite), "composite");
  EXPECT_STREQ(pyro::ecs::phase_name(Phase::output), "output");
}

TEST(Schedule, PhaseOrderThenInsertionOrder) {
  std::vector<std::string> log;
  Schedule s;
  s.set_threads(1);  // the sequential schedule: systems that do not conflict run in this order
  s.add(logger("write_png", Phase::output, &log));
  s.add(logger("draw_a", Phase::render, &log));
  s.add(logger("emit", Phase::spawn, &log));
  s.add(logger("draw_b", Phase::render, &log));
  s.add(logger("blend", Phase::composite, &log));
  s.add(logger("move", Phase::simulate, &log));
  s.add(logger("depth_sort", Phase::sort, &log));
  s.add(logger("eyes", Phase::camera, &log));
  s.add(logger("draw_c", Phase::render, &log));
  s.add(logger("age", Phase::simulate, &log));
  s.add(logger("emit_late", Phase::spawn, &log));

  // Data-flow order: the camera makes the eye frames before the sort uses them.
  const std::vector<std::string> expected{"emit",   "emit_late",  "move",     "age",
                                          "eyes",   "depth_sort", "draw_a",   "draw_b",
                                          "draw_c", "blend",      "write_png"};
  EXPECT_EQ(s.order(), expected);
  World w;
  s.run_frame(w);
  EXPECT_EQ(log, expected);
  s.run_frame(w);
  ASSERT_EQ(log.size(), 2 * expected.size());
  EXPECT_TRUE(std::equal(expected.begin(), expected.end(), log.begin() + 11));
  ASSERT_EQ(s.stats().size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(s.stats()[i].name, expected[i]);
}

TEST(Schedule, SystemsSeeTheWorld) {
  Schedule s;
  s.add({.name = "spawn",
         .phase = Phase::spawn,
         .access = Access::of<Writes<pyro::ecs::Entities, SchedulePosition, ScheduleVelocity>>(),
         .run = [](World& w) {
           const auto e = w.create();
           w.emplace<SchedulePosition>(e, 0.0f);
           w.emplace<ScheduleVelocity>(e, 2.0f);
         }});
  s.add({.name = "move",
         .phase = Phase::simulate,
         .access = Access::of<Reads<ScheduleVelocity>, Writes<SchedulePosition>>(),
         .run = [](World& w) {
           w.each<SchedulePosition, const ScheduleVelocity>([](SchedulePosition& p, const ScheduleVelocity& v) { p.x += v.x; });
         }});
  World w;
  for (int i = 0; i < 3; ++i) s.run_frame(w);
  // Entities spawned in frames 1, 2, 3 have moved 3, 2, 1 times.
  float sum = 0;
  w.each<SchedulePosition>([&](SchedulePosition& p) { sum += p.x; });
  EXPECT_EQ(sum, 2.0f * (3 + 2 + 1));
}

TEST(Schedule, TimingsEveryFrame) {
  Schedule s;
  s.add({.name = "busy", .phase = Phase::simulate, .run = [](World&) {
           // Spin rather than sleep: the time must be spent inside the system.
           const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(300);
           while (std::chrono::steady_clock::now() < until) {
           }
         }});
  // Sleeps a known 2 ms: its timing must cover the sleep (a clock read in the wrong place, or
  // timing that is never recorded, gives less).
  s.add({.name = "sleepy", .phase = Phase::render, .run = [](World&) {
           std::this_thread::sleep_for(std::chrono::milliseconds(2));
         }});
  World w;
  double sum_last = 0;
  for (int f = 1; f <= 5; ++f) {
    s.run_frame(w);
    const auto& busy = s.stats()[0];
    EXPECT_EQ(busy.name, "busy");
    EXPECT_EQ(busy.frames, uint64_t(f));
    EXPECT_GE(busy.last_ms, 0.3);
    EXPECT_GE(busy.total_ms, busy.last_ms);
    EXPECT_GE(busy.max_ms, busy.last_ms);
    sum_last += busy.last_ms;
    EXPECT_NEAR(busy.total_ms, sum_last, 1e-9);
    EXPECT_NEAR(busy.mean_ms(), sum_last / f, 1e-9);
    EXPECT_EQ(s.stats()[1].name, "sleepy");
    EXPECT_EQ(s.stats()[1].frames, uint64_t(f));
    EXPECT_GE(s.stats()[1].last_ms, 2.0);
  }
  EXPECT_EQ(s.frames(), 5u);
  EXPECT_EQ(pyro::ecs::SystemStats{}.mean_ms(), 0.0);
}

TEST(Schedule, RejectsBadSystems) {
  Schedule s;
  std::vector<std::string> log;
  s.add(logger("move", Phase::simulate, &log));
  EXPECT_THROW(s.add(logger("move", Phase::render, &log)), std::invalid_argument);
  EXPECT_THROW(s.add(logger("", Phase::render, &log)), std::invalid_argument);
  SystemDesc empty;
  empty.name = "nothing";
  EXPECT_THROW(s.add(empty), std::invalid_argument);
  EXPECT_EQ(s.size(), 1u);
  EXPECT_EQ(s.stats().size(), 1u);
}

TEST(Schedule, ConflictsWithinAPhase) {
  std::vector<std::string> log;
  Schedule s;
  s.add(
      logger("integrate", Phase::simulate, &log, Access::of<Reads<ScheduleVelocity>, Writes<SchedulePosition>>()));
  s.add(logger("collide", Phase::simulate, &log, Access::of<Reads<SchedulePosition>, Writes<ScheduleVelocity>>()));
  s.add(logger("age", Phase::simulate, &log, Access::of<Writes<Image>>()));  // disjoint
  s.add(logger("bounds", Phase::simulate, &log, Access::of<Reads<SchedulePosition>>()));
  s.add(logger("draw", Phase::render, &log,  // other phase
               Access::of<Reads<SchedulePosition>, Writes<Image>>()));
  s.add(logger("blur", Phase::render, &log, Access::of<Reads<Image>, Writes<Image>>()));
  s.add(
      logger("stats", Phase::output, &log, Access::of<Reads<SchedulePosition>>()));  // readers never clash
  s.add(logger("hud", Phase::output, &log, Access::of<Reads<SchedulePosition>>()));
  s.add(logger("teleport", Phase::output, &log,  // later writer vs earlier readers
               Access::of<Writes<SchedulePosition>>()));

  const std::vector<std::pair<std::string, std::string>> expected{{"integrate", "collide"},
                                                                  {"integrate", "bounds"},
                                                                  {"draw", "blur"},
                                                                  {"stats", "teleport"},
                                                                  {"hud", "teleport"}};
  EXPECT_EQ(s.conflicts(), expected);
}

}  // namespace

namespace {

TEST(Schedule, RunPhasesRunsOnlyTheSystemsInTheRange) {
  std::vector<std::string> log;
  Schedule s;
  s.add(logger("emit", Phase::spawn, &log));
  s.add(logger("move", Phase::simulate, &log));
  s.add(logger("sort", Phase::sort, &log));
  s.add(logger("draw", Phase::render, &log));
  s.add(logger("write", Phase::output, &log));
  World w;
  s.run_phases(w, Phase::sort, Phase::output);
  EXPECT_EQ(log, (std::vector<std::string>{"sort", "draw", "write"}));
  log.clear();
  s.run_phases(w, Phase::simulate, Phase::render);
  EXPECT_EQ(log, (std::vector<std::string>{"move", "sort", "draw"}));
  EXPECT_EQ(s.stats()[0].frames, 0u);  // emit never ran
  EXPECT_EQ(s.stats()[2].frames, 2u);  // sort ran twice
  EXPECT_EQ(s.frames(), 0u);           // only run_frame counts frames
}

}  // namespace

namespace {

TEST(Schedule, AfterOrdersAConflictingPair) {
  std::vector<std::string> log;
  Schedule s;
  const Access writes_position = Access::of<Writes<SchedulePosition>>();
  s.add(logger("integrate", Phase::simulate, &log, writes_position));
  s.add(logger("collide", Phase::simulate, &log, writes_position));
  s.add(logger("bounds", Phase::simulate, &log, Access::of<Reads<SchedulePosition>>(), {"collide"}));
  s.add(logger("draw", Phase::render, &log, Access::of<Reads<SchedulePosition>>(), {"integrate"}));
  // integrate/collide conflict unordered; collide -> bounds is declared; integrate -> bounds
  // conflicts but is not ordered by any chain.
  EXPECT_TRUE(s.ordered("collide", "bounds"));
  EXPECT_FALSE(s.ordered("integrate", "bounds"));
  EXPECT_FALSE(s.ordered("bounds", "collide"));
  const std::vector<std::pair<std::string, std::string>> unordered{{"integrate", "collide"},
                                                                   {"integrate", "bounds"}};
  EXPECT_EQ(s.unordered_conflicts(), unordered);

  // A chain orders transitively.
  s.add(logger("settle", Phase::simulate, &log, writes_position, {"bounds"}));
  EXPECT_TRUE(s.ordered("collide", "settle"));
  EXPECT_FALSE(s.ordered("integrate", "settle"));
}

TEST(Schedule, AfterMustNameAnEarlierSystem) {
  std::vector<std::string> log;
  Schedule s;
  s.add(logger("draw", Phase::render, &log));
  // Not yet added, or in a later phase: refused, and the schedule is unchanged.
  EXPECT_THROW(s.add(logger("move", Phase::simulate, &log, {}, {"nothing"})),
               std::invalid_argument);
  EXPECT_THROW(s.add(logger("move", Phase::simulate, &log, {}, {"draw"})), std::invalid_argument);
  EXPECT_EQ(s.size(), 1u);
  s.add(logger("blend", Phase::composite, &log, {}, {"draw"}));  // an earlier phase is fine
  EXPECT_EQ(s.size(), 2u);
}

TEST(Schedule, SetupRunsOnceInOrderBeforeFrames) {
  std::vector<std::string> log;
  Schedule s;
  SystemDesc draw = logger("draw", Phase::render, &log);
  draw.setup = [&log](World&) { log.push_back("setup draw"); };
  SystemDesc move = logger("move", Phase::simulate, &log);
  move.setup = [&log](World&) { log.push_back("setup move"); };
  s.add(std::move(draw));
  s.add(std::move(move));
  s.add(logger("idle", Phase::output, &log));  // no setup
  World w;
  s.setup(w);
  EXPECT_EQ(log, (std::vector<std::string>{"setup move", "setup draw"}));
  s.run_frame(w);
  EXPECT_EQ(log, (std::vector<std::string>{"setup move", "setup draw", "move", "draw", "idle"}));
}

}  // namespace

namespace {

TEST(Schedule, RunSystemOnceRunsSetupThenRunUnderTheDeclaration) {
  World w;
  SystemDesc count;
  count.name = "count";
  count.access = Access::of<Writes<Image>>();
  count.setup = [](World& world) { world.set_resource<Image>(Image{1}); };
  count.run = [](World& world) { world.resource<Image>().w *= 10; };
  pyro::ecs::run_system_once(count, w);
  EXPECT_EQ(w.resource<Image>().w, 10);  // setup first, then run
  SystemDesc sneaky = count;
  sneaky.name = "sneaky";
  sneaky.setup = nullptr;
  sneaky.run = [](World& world) { world.set_resource<SchedulePosition>(); };
  EXPECT_THROW(pyro::ecs::run_system_once(sneaky, w), std::logic_error);
  EXPECT_FALSE(w.has_resource<SchedulePosition>());
  EXPECT_EQ(pyro::ecs::running_system(), nullptr);
}

}  // namespace
