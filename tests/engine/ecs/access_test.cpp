// Access declared by type and checked while a system runs under the schedule: an undeclared
// read, a write to a type declared only as read, an undeclared resource, an undeclared entity
// change each throw std::logic_error naming the system and the type; declared accesses pass,
// and nothing is checked outside a scheduled system.
#include "engine/ecs/access.h"

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <thread>

#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"

namespace {

using pyro::ecs::Access;
using pyro::ecs::AccessMode;
using pyro::ecs::Entities;
using pyro::ecs::Entity;
using pyro::ecs::Phase;
using pyro::ecs::Reads;
using pyro::ecs::Schedule;
using pyro::ecs::SystemDesc;
using pyro::ecs::World;
using pyro::ecs::Writes;

struct Position {
  float x = 0;
};
struct Velocity {
  float x = 0;
};
struct Gravity {
  float g = -9.8f;
};
struct Undeclared {
  int n = 0;
};

// A world with one entity holding a Position and a Velocity, and a Gravity resource.
struct Fixture {
  World world;
  Entity e;
  Fixture() {
    e = world.create();
    world.emplace<Position>(e, 1.0f);
    world.emplace<Velocity>(e, 2.0f);
    world.emplace<Undeclared>(e, 3);
    world.set_resource<Gravity>();
  }
  // Runs `body` once as the system "mover" with the given access.
  void run(Access access, std::function<void(World&, Entity)> body) {
    Schedule s;
    const Entity entity = e;
    s.add({.name = "mover",
           .phase = Phase::simulate,
           .access = std::move(access),
           .run = [body, entity](World& w) { body(w, entity); }});
    s.run_frame(world);
  }
};

// The message of the logic_error `f` throws ("" if it throws none).
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::logic_error& err) {
    return err.what();
  }
  return "";
}

const Access kMoverAccess = Access::of<Reads<Velocity, Gravity>, Writes<Position>>();

TEST(Access, DeclaredByTypeWithNamesAndModes) {
  const Access a = Access::of<Reads<Velocity, Gravity>, Writes<Position>, Reads<Position>>();
  EXPECT_EQ(a.mode(pyro::ecs::type_id<Velocity>()), AccessMode::read);
  EXPECT_EQ(a.mode(pyro::ecs::type_id<Position>()), AccessMode::write);  // write wins
  EXPECT_EQ(a.mode(pyro::ecs::type_id<Undeclared>()), AccessMode::none);
  EXPECT_TRUE(a.allows(pyro::ecs::type_id<Position>(), AccessMode::read));
  EXPECT_FALSE(a.allows(pyro::ecs::type_id<Velocity>(), AccessMode::write));
  ASSERT_EQ(a.read_names().size(), 2u);
  EXPECT_NE(a.read_names()[0].find("Velocity"), std::string::npos);
  EXPECT_NE(a.read_names()[1].find("Gravity"), std::string::npos);
  ASSERT_EQ(a.write_names().size(), 1u);
  EXPECT_NE(a.write_names()[0].find("Position"), std::string::npos);
}

TEST(Access, ConflictWhenOneWritesWhatTheOtherTouches) {
  const Access move = Access::of<Reads<Velocity>, Writes<Position>>();
  const Access draw = Access::of<Reads<Position>>();
  const Access hud = Access::of<Reads<Position, Velocity>>();
  const Access spawn = Access::of<Writes<Entities>>();
  EXPECT_TRUE(move.conflicts_with(draw));
  EXPECT_TRUE(draw.conflicts_with(move));
  EXPECT_FALSE(draw.conflicts_with(hud));  // readers never clash
  EXPECT_FALSE(move.conflicts_with(Access::of<Writes<Gravity>>()));
  // Changing the entity table conflicts with every system, even one that declares nothing.
  EXPECT_TRUE(spawn.conflicts_with(Access{}));
  EXPECT_TRUE(Access{}.conflicts_with(spawn));
}

TEST(Access, DeclaredAccessesPass) {
  Fixture f;
  f.run(kMoverAccess, [](World& w, Entity e) {
    const float g = w.resource<const Gravity>().g;
    w.each<Position, const Velocity>([g](Position& p, const Velocity& v) { p.x += v.x + g; });
    w.get<Position>(e).x += w.get<const Velocity>(e).x;
    EXPECT_TRUE(w.has<Velocity>(e));
    EXPECT_NE(w.try_get<const Velocity>(e), nullptr);
    EXPECT_EQ((w.count<Position, Velocity>()), 1u);
    EXPECT_EQ(std::as_const(w).get<Velocity>(e).x, 2.0f);  // const World: a read
    EXPECT_TRUE(w.has_resource<Gravity>());
  });
  EXPECT_FLOAT_EQ(f.world.get<Position>(f.e).x, 1.0f + 2.0f - 9.8f + 2.0f);
}

TEST(Access, ReadingAnUndeclaredComponentThrowsNamingSystemAndType) {
  Fixture f;
  for (auto read : std::initializer_list<std::function<void(World&, Entity)>>{
           [](World&w, Entity e) { (void)w.get<const Undeclared>(e); },
           [](World&w, Entity e) { (void)w.try_get<const Undeclared>(e); },
           [](World&w, Entity e) { (void)w.has<Undeclared>(e); },
           [](World&w, Entity) { w.each<const Undeclared>([](const Undeclared&) {}); },
           [](World&w, Entity) { (void)w.count<Position, Undeclared>(); },
           [](World&w, Entity) { (void)w.pool<Undeclared>(); },
           [](World&w, Entity) { (void)w.size<Undeclared>(); },
       }) {
    const std::string what = error_of([&] { f.run(kMoverAccess, read); });
    EXPECT_NE(what.find("system 'mover'"), std::string::npos) << what;
    EXPECT_NE(what.find("reads"), std::string::npos) << what;
    EXPECT_NE(what.find("Undeclared"), std::string::npos) << what;
    EXPECT_NE(what.find("does not declare it"), std::string::npos) << what;
  }
}

TEST(Access, WritingAComponentDeclaredReadOnlyThrows) {
  Fixture f;
  for (auto write : std::initializer_list<std::function<void(World&, Entity)>>{
           [](World&w, Entity e) { w.get<Velocity>(e).x = 0; },
           [](World&w, Entity e) { (void)w.try_get<Velocity>(e); },
           [](World&w, Entity) { w.each<Position, Velocity>([](Position&, Velocity&) {}); },
           [](World&w, Entity e) { w.remove<Velocity>(e); },
           [](World&w, Entity) { w.resource<Gravity>().g = 0; },
       }) {
    const std::string what = error_of([&] { f.run(kMoverAccess, write); });
    EXPECT_NE(what.find("system 'mover'"), std::string::npos) << what;
    EXPECT_NE(what.find("writes"), std::string::npos) << what;
    EXPECT_TRUE(what.find("Velocity") != std::string::npos ||
                what.find("Gravity") != std::string::npos)
        << what;
    EXPECT_NE(what.find("declares it only as a read"), std::string::npos) << what;
  }
  EXPECT_EQ(f.world.get<Velocity>(f.e).x, 2.0f);  // refused before anything changed
  EXPECT_TRUE(f.world.has<Velocity>(f.e));
}

TEST(Access, UndeclaredResourceThrows) {
  Fixture f;
  struct Score {
    int points = 0;
  };
  for (auto touch : std::initializer_list<std::function<void(World&, Entity)>>{
           [](World&w, Entity) { (void)w.try_resource<const Score>(); },
           [](World&w, Entity) { (void)w.has_resource<Score>(); },
           [](World&w, Entity) { w.set_resource<Score>(); },
           [](World&w, Entity) { w.remove_resource<Score>(); },
       }) {
    const std::string what = error_of([&] { f.run(kMoverAccess, touch); });
    EXPECT_NE(what.find("system 'mover'"), std::string::npos) << what;
    EXPECT_NE(what.find("Score"), std::string::npos) << what;
  }
  EXPECT_FALSE(f.world.has_resource<Score>());
}

TEST(Access, EntityChangesNeedWritesEntities) {
  Fixture f;
  const std::string create =
      error_of([&] { f.run(kMoverAccess, [](World& w, Entity) { w.create(); }); });
  EXPECT_NE(create.find("Entities"), std::string::npos) << create;
  const std::string destroy =
      error_of([&] { f.run(kMoverAccess, [](World& w, Entity e) { w.destroy(e); }); });
  EXPECT_NE(destroy.find("Entities"), std::string::npos) << destroy;
  EXPECT_TRUE(f.world.alive(f.e));
  // With the entity table declared, destroying still needs a write of every component it holds.
  const std::string components = error_of([&] {
    f.run(Access::of<Writes<Entities, Position, Velocity>>(),
          [](World& w, Entity e) { w.destroy(e); });
  });
  EXPECT_NE(components.find("Undeclared"), std::string::npos) << components;
  EXPECT_TRUE(f.world.alive(f.e));
  f.run(Access::of<Writes<Entities, Position, Velocity, Undeclared>>(),
        [](World& w, Entity e) { w.destroy(e); });
  EXPECT_FALSE(f.world.alive(f.e));
}

TEST(Access, SetupIsCheckedLikeRun) {
  World w;
  Schedule s;
  s.add({.name = "maker",
         .phase = Phase::render,
         .access = Access::of<Reads<Gravity>>(),
         .run = [](World&) {},
         .setup = [](World& world) { world.set_resource<Gravity>(); }});
  const std::string what = error_of([&] { s.setup(w); });
  EXPECT_NE(what.find("system 'maker'"), std::string::npos) << what;
  EXPECT_NE(what.find("Gravity"), std::string::npos) << what;
}

TEST(Access, OutsideAScheduledSystemNothingIsChecked) {
  Fixture f;
  EXPECT_EQ(pyro::ecs::running_system(), nullptr);
  f.world.get<Undeclared>(f.e).n = 4;
  f.world.set_resource<Gravity>(Gravity{1.0f});
  f.world.destroy(f.world.create());
  // After a system ran (and after one threw), the thread is back outside any system.
  f.run(kMoverAccess, [](World&, Entity) { EXPECT_NE(pyro::ecs::running_system(), nullptr); });
  EXPECT_EQ(pyro::ecs::running_system(), nullptr);
  (void)error_of([&] { f.run(kMoverAccess, [](World& w, Entity) { w.create(); }); });
  EXPECT_EQ(pyro::ecs::running_system(), nullptr);
  EXPECT_EQ(f.world.get<Undeclared>(f.e).n, 4);
}

TEST(Access, TheRunningSystemIsPerThread) {
  // Another thread, while a system runs here, is outside any system and unchecked.
  Fixture f;
  f.run(kMoverAccess, [](World& w, Entity e) {
    std::thread other([&] {
      EXPECT_EQ(pyro::ecs::running_system(), nullptr);
      w.get<Undeclared>(e).n = 9;
    });
    other.join();
    EXPECT_THROW((void)w.get<const Undeclared>(e), std::logic_error);
  });
  EXPECT_EQ(f.world.get<Undeclared>(f.e).n, 9);
}

}  // namespace
