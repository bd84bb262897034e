// The world against a deliberately simple model (std::map of live entities with optional
// component values), over long random operation sequences. Every step is followed by a full
// comparison: liveness, component presence and values, pool consistency, each<> results,
// stale handles, and the owning-group packing invariant.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <unordered_set>
#include <vector>

#include "engine/ecs/world.h"

namespace {

using pyro::ecs::Entity;
using pyro::ecs::World;

template <int K>
struct C {
  int v = 0;
};

struct Outsider {
  int v = 0;
};

enum class GroupWhen { never, start, midway };

// The per-step checks run millions of times; gtest's ASSERT machinery would dominate the run
// time, so they use this plain test-and-report instead (the step is reported by run()).
#define MODEL_CHECK(cond) \
  if (cond) {             \
  } else                  \
    return (void)(ADD_FAILURE() << "model check failed: " << #cond)

template <class F>
bool throws(F&& f) {
  try {
    f();
  } catch (const std::logic_error&) {
    return true;
  }
  return false;
}

// Calls f.template operator()<k>() for a runtime k in [0, 4).
template <class F>
void with_type(int k, F&& f) {
  switch (k) {
    case 0:
      f.template operator()<0>();
      break;
    case 1:
      f.template operator()<1>();
      break;
    case 2:
      f.template operator()<2>();
      break;
    case 3:
      f.template operator()<3>();
      break;
    default:
      FAIL() << "bad type index " << k;
  }
}

// NT component types C<0>..C<NT-1>; the group (if any) owns C<G>... .
template <int NT, int... G>
class ModelRun {
  static_assert(NT >= 2 && NT <= 4);

 public:
  ModelRun(uint32_t seed, int steps, GroupWhen when) : rng_(seed), steps_(steps), when_(when) {
    if constexpr (sizeof...(G) == 0) when_ = GroupWhen::never;
    build_subset_checks();
  }

  void run() {
    if (when_ == GroupWhen::start) declare_group();
    for (step_ = 0; step_ < steps_; ++step_) {
      if (when_ == GroupWhen::midway && step_ == steps_ / 2) declare_group();
      one_step();
      check_all();
      if (::testing::Test::HasFailure()) {
        ADD_FAILURE() << "stopped at step " << step_;
        return;
      }
    }
    // The run must actually have exercised the interesting paths.
    EXPECT_GT(destroys_, steps_ / 50);
    EXPECT_GT(stale_checks_, steps_ / 50);
    if (when_ != GroupWhen::never) {
      EXPECT_GT(max_group_size_, 0u);
    }
  }

 private:
  struct Rec {
    Entity e;
    std::array<std::optional<int>, 4> c;
  };

  // ---- random helpers ------------------------------------------------------------------------
  int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  int random_type() { return uniform(0, NT - 1); }
  Rec& random_live() {
    auto it = live_.begin();
    std::advance(it, uniform(0, int(live_.size()) - 1));
    return it->second;
  }

  void declare_group() {
    if constexpr (sizeof...(G) > 0) {
      world_.group<C<G>...>();
      group_declared_ = true;
      // A second declaration of the same set is a no-op; a clashing one throws.
      world_.group<C<G>...>();
      EXPECT_THROW((world_.group<C<G>..., Outsider>()), std::logic_error)
          << "a pool owned by a group must refuse a second owner";
    }
  }

  // ---- one random operation ----------------------------------------------------------------
  void one_step() {
    const int target = 48;
    const int n = int(live_.size());
    // Weights: create, destroy, emplace, remove, get/set, each-mutate, stale, locked-change.
    std::array<int, 8> w{n < target ? 14 : 7, n > target ? 14 : 7, 24, 14, 14, 4, 6, 1};
    if (n == 0) w = {1, 0, 0, 0, 0, 0, stale_.empty() ? 0 : 1, 0};
    std::discrete_distribution<int> pick(w.begin(), w.end());
    switch (pick(rng_)) {
      case 0:
        op_create();
        break;
      case 1:
        op_destroy();
        break;
      case 2:
        op_emplace();
        break;
      case 3:
        op_remove();
        break;
      case 4:
        op_get_set();
        break;
      case 5:
        op_each_mutate();
        break;
      case 6:
        op_stale();
        break;
      case 7:
        op_change_while_iterating();
        break;
    }
  }

  void op_create() {
    const Entity e = world_.create();
    ASSERT_TRUE(world_.alive(e));
    ASSERT_EQ(live_.count(e.index), 0u) << "index of a live entity handed out again";
    live_[e.index] = Rec{e, {}};
  }

  void op_destroy() {
    const Entity e = random_live().e;
    world_.destroy(e);
    live_.erase(e.index);
    stale_.push_back(e);
    if (stale_.size() > 512) stale_.erase(stale_.begin());
    ++destroys_;
    EXPECT_FALSE(world_.alive(e));
  }

  void op_emplace() {
    Rec& rec = random_live();
    with_type(random_type(), [&]<int K>() {
      if (rec.c[K]) {
        EXPECT_THROW(world_.emplace<C<K>>(rec.e, 0), std::logic_error);
        return;
      }
      const int v = uniform(-1000000, 1000000);
      C<K>& ref = world_.emplace<C<K>>(rec.e, v);
      EXPECT_EQ(ref.v, v);
      EXPECT_EQ(&ref, &world_.get<C<K>>(rec.e)) << "emplace must return the stored component";
      rec.c[K] = v;
    });
  }

  void op_remove() {
    Rec& rec = random_live();
    with_type(random_type(), [&]<int K>() {
      if (!rec.c[K]) {
        EXPECT_THROW(world_.remove<C<K>>(rec.e), std::logic_error);
        return;
      }
      world_.remove<C<K>>(rec.e);
      rec.c[K].reset();
    });
  }

  void op_get_set() {
    Rec& rec = random_live();
    with_type(random_type(), [&]<int K>() {
      if (!rec.c[K]) {
        EXPECT_THROW(world_.get<C<K>>(rec.e), std::logic_error);
        EXPECT_EQ(world_.try_get<C<K>>(rec.e), nullptr);
        return;
      }
      const int v = uniform(-1000000, 1000000);
      world_.get<C<K>>(rec.e).v = v;
      rec.c[K] = v;
    });
  }

  // Mutates through each<> (the f(Ts&...) form), on the group's set or a random pair.
  void op_each_mutate() {
    auto apply = [&]<int... Ks>() {
      world_.each<C<Ks>...>([](C<Ks>&... c) { ((c.v += Ks + 1), ...); });
      for (auto& [index, rec] : live_)
        if ((rec.c[Ks] && ...)) ((*rec.c[Ks] += Ks + 1), ...);
    };
    if constexpr (sizeof...(G) > 0) {
      if (uniform(0, 1) == 0) return apply.template operator()<G...>();
    }
    if (uniform(0, 1) == 0) {
      apply.template operator()<NT - 1, 0>();
    } else {
      apply.template operator()<1>();
    }
  }

  void op_stale() {
    if (stale_.empty()) return;
    const Entity e = stale_[std::size_t(uniform(0, int(stale_.size()) - 1))];
    with_type(random_type(), [&]<int K>() {
      switch (uniform(0, 5)) {
        case 0:
          EXPECT_THROW(world_.emplace<C<K>>(e, 1), std::logic_error);
          break;
        case 1:
          EXPECT_THROW(world_.remove<C<K>>(e), std::logic_error);
          break;
        case 2:
          EXPECT_THROW(world_.get<C<K>>(e), std::logic_error);
          break;
        case 3:
          EXPECT_THROW(world_.try_get<C<K>>(e), std::logic_error);
          break;
        case 4:
          EXPECT_THROW(world_.has<C<K>>(e), std::logic_error);
          break;
        case 5:
          EXPECT_THROW(world_.destroy(e), std::logic_error);
          break;
      }
    });
  }

  // Structural changes to a pool while each<> walks it must be refused and change nothing.
  void op_change_while_iterating() {
    Rec& other = random_live();
    bool threw = false;
    bool visited = false;
    world_.each<C<0>>([&](Entity, C<0>&) {
      if (visited) return;
      visited = true;
      try {
        if (other.c[0])
          world_.remove<C<0>>(other.e);
        else
          world_.emplace<C<0>>(other.e, 5);
      } catch (const std::logic_error&) {
        threw = true;
      }
    });
    EXPECT_EQ(threw, visited);
    // Creating entities is fine mid-loop (it touches no pool); undo it afterwards.
    bool created = false;
    world_.each<C<1>>([&](C<1>&) {
      if (created) return;
      created = true;
      const Entity e = world_.create();
      live_[e.index] = Rec{e, {}};
    });
  }

  // ---- checks --------------------------------------------------------------------------------
  void check_all() {
    MODEL_CHECK(world_.entity_count() == live_.size());
    std::array<std::size_t, 4> counts{};
    for (const auto& [index, rec] : live_) {
      MODEL_CHECK(world_.alive(rec.e));
      for (int k = 0; k < NT; ++k) {
        with_type(k, [&]<int K>() {
          const C<K>* p = world_.try_get<C<K>>(rec.e);
          MODEL_CHECK(world_.has<C<K>>(rec.e) == rec.c[K].has_value());
          MODEL_CHECK((p != nullptr) == rec.c[K].has_value());
          if (p) {
            MODEL_CHECK(p->v == *rec.c[K]);
            MODEL_CHECK(world_.get<C<K>>(rec.e).v == *rec.c[K]);
            ++counts[K];
          }
        });
      }
    }
    for (int k = 0; k < NT; ++k)
      with_type(k, [&]<int K>() {
        MODEL_CHECK(world_.size<C<K>>() == counts[K]);
        check_pool<K>();
      });

    // One stale handle per step (op_stale tries the other accesses): dead, and access throws.
    if (!stale_.empty()) {
      const Entity e = stale_[std::size_t(uniform(0, int(stale_.size()) - 1))];
      MODEL_CHECK(!world_.alive(e));
      MODEL_CHECK(throws([&] { (void)world_.has<C<0>>(e); }));
      ++stale_checks_;
    }
    MODEL_CHECK(!world_.alive(Entity::null));

    if constexpr (sizeof...(G) > 0) {
      if (group_declared_) {
        check_group();
        check_each<G...>();
      }
    }
    subset_checks_[std::size_t(step_) % subset_checks_.size()]();
  }

  // Pool internals: sparse and dense agree, every slot belongs to a live owner of K.
  template <int K>
  void check_pool() {
    const auto* pool = world_.pool<C<K>>();
    if (!pool) return;
    const auto& ents = pool->entities();
    for (std::size_t s = 0; s < pool->size(); ++s) {
      const Entity e = ents[s];
      MODEL_CHECK(pool->contains(e.index));
      MODEL_CHECK(pool->slot(e.index) == s);
      auto it = live_.find(e.index);
      MODEL_CHECK(it != live_.end() && it->second.e == e);  // no dead owners
      MODEL_CHECK(it->second.c[K].has_value());
      MODEL_CHECK(pool->data()[s].v == *it->second.c[K]);
    }
  }

  // Members (entities with all of G) fill slots [0, size) of each owned pool, in one order.
  void check_group() {
    if constexpr (sizeof...(G) > 0) {
      std::set<uint32_t> members;
      for (const auto& [index, rec] : live_)
        if ((rec.c[G] && ...)) members.insert(index);
      const std::size_t gs = world_.group_size<C<G>...>();
      MODEL_CHECK(gs == members.size());
      max_group_size_ = std::max(max_group_size_, gs);
      const std::array<const std::vector<Entity>*, sizeof...(G)> ents{
          &world_.pool<C<G>>()->entities()...};
      for (std::size_t i = 0; i < gs; ++i) {
        for (const auto* e : ents) MODEL_CHECK((*e)[i] == (*ents[0])[i]);  // same order
        MODEL_CHECK(members.count((*ents[0])[i].index) == 1u);
      }
      MODEL_CHECK(world_.count<C<G>...>() == gs);
    }
  }

  // each<Ks...> with f(Entity, Ks&...) visits exactly the model's set, once each, with the
  // model's values.
  template <int... Ks>
  void check_each() {
    std::map<uint32_t, std::array<int, sizeof...(Ks)>> seen;
    bool duplicate = false;
    world_.each<C<Ks>...>([&](Entity e, C<Ks>&... c) {
      auto [it, fresh] = seen.emplace(e.index, std::array<int, sizeof...(Ks)>{c.v...});
      duplicate = duplicate || !fresh || !(live_.count(e.index) && live_[e.index].e == e);
    });
    MODEL_CHECK(!duplicate);  // nobody twice, nobody dead
    std::size_t expected = 0;
    for (const auto& [index, rec] : live_) {
      if (!(rec.c[Ks] && ...)) continue;
      ++expected;
      auto it = seen.find(index);
      MODEL_CHECK(it != seen.end());  // nobody missed
      MODEL_CHECK(it->second == (std::array<int, sizeof...(Ks)>{*rec.c[Ks]...}));
    }
    MODEL_CHECK(seen.size() == expected);
    MODEL_CHECK(world_.count<C<Ks>...>() == expected);
  }

  void build_subset_checks() {
    auto add = [&]<int... Ks>() {
      subset_checks_.push_back([this] { check_each<Ks...>(); });
    };
    add.template operator()<0>();
    add.template operator()<1>();
    add.template operator()<0, 1>();
    add.template operator()<1, 0>();
    if constexpr (NT >= 3) {
      add.template operator()<2>();
      add.template operator()<2, 0>();
      add.template operator()<2, 1>();
      add.template operator()<0, 1, 2>();
      add.template operator()<2, 0, 1>();
    }
    if constexpr (NT >= 4) {
      add.template operator()<3>();
      add.template operator()<3, 1>();
      add.template operator()<3, 1, 0>();
      add.template operator()<1, 2, 3>();
      add.template operator()<0, 1, 2, 3>();
      add.template operator()<3, 2, 1, 0>();
    }
  }

  World world_;
  std::mt19937 rng_;
  int steps_;
  int step_ = 0;
  GroupWhen when_;
  bool group_declared_ = false;
  std::map<uint32_t, Rec> live_;
  std::vector<Entity> stale_;
  std::vector<std::function<void()>> subset_checks_;
  int destroys_ = 0;
  int stale_checks_ = 0;
  std::size_t max_group_size_ = 0;
};

constexpr int kSteps = 100000;

TEST(WorldModel, TwoTypesGroupAtStart) { ModelRun<2, 0, 1>(1, kSteps, GroupWhen::start).run(); }
TEST(WorldModel, TwoTypesGroupMidway) { ModelRun<2, 1, 0>(2, kSteps, GroupWhen::midway).run(); }
TEST(WorldModel, ThreeTypesGroupMidway) { ModelRun<3, 0, 2>(3, kSteps, GroupWhen::midway).run(); }
TEST(WorldModel, ThreeTypesGroupAtStart) { ModelRun<3, 2, 1>(4, kSteps, GroupWhen::start).run(); }
TEST(WorldModel, FourTypesGroupMidway) { ModelRun<4, 0, 1, 3>(5, kSteps, GroupWhen::midway).run(); }
TEST(WorldModel, FourTypesFullGroupAtStart) {
  ModelRun<4, 3, 2, 1, 0>(6, kSteps, GroupWhen::start).run();
}
TEST(WorldModel, FourTypesSingleTypeGroupMidway) {
  ModelRun<4, 2>(7, kSteps, GroupWhen::midway).run();
}

// Without a group the each<> path that looks components up must agree with the model too.
TEST(WorldModel, ThreeTypesNoGroup) { ModelRun<3>(8, kSteps, GroupWhen::never).run(); }

// ---- closed facts that the random runs do not pin down -----------------------------------

struct WorldModelPosition {
  float x, y, z;
};
struct WorldModelVelocity {
  float x, y, z;
};
struct Settings {
  int quality = 3;
};

TEST(World, EntityHandles) {
  World w;
  const Entity a = w.create();
  EXPECT_EQ(a, (Entity{0, 0}));
  w.destroy(a);
  const Entity b = w.create();
  EXPECT_EQ(b.index, a.index) << "indices are recycled";
  EXPECT_EQ(b.generation, a.generation + 1);
  EXPECT_FALSE(w.alive(a));
  EXPECT_TRUE(w.alive(b));
  EXPECT_NE(a, b);
  EXPECT_TRUE(Entity{}.is_null());
  EXPECT_EQ(Entity{}, Entity::null);
  EXPECT_FALSE(w.alive(Entity::null));
  EXPECT_THROW(w.has<WorldModelPosition>(Entity::null), std::logic_error);
  // A forged handle with a future generation is not alive either.
  w.destroy(b);
  EXPECT_FALSE(w.alive(Entity{b.index, b.generation + 1}));
  EXPECT_EQ(w.entity_count(), 0u);

  std::unordered_set<Entity> set{Entity{1, 0}, Entity{1, 1}, Entity{0, 1}, Entity{1, 0}};
  EXPECT_EQ(set.size(), 3u);
  EXPECT_NE(std::hash<Entity>{}(Entity{1, 0}), std::hash<Entity>{}(Entity{1, 1}));
}

TEST(World, ComponentErrorsNameTheType) {
  World w;
  const Entity e = w.create();
  w.emplace<WorldModelPosition>(e, 1.0f, 2.0f, 3.0f);
  EXPECT_THROW(w.emplace<WorldModelPosition>(e), std::logic_error);
  try {
    w.get<WorldModelVelocity>(e);
    FAIL() << "get of an absent component must throw";
  } catch (const std::logic_error& err) {
    EXPECT_NE(std::string(err.what()).find("Velocity"), std::string::npos) << err.what();
  }
  EXPECT_THROW(w.remove<WorldModelVelocity>(e), std::logic_error);
  EXPECT_EQ(w.get<WorldModelPosition>(e).y, 2.0f);
  const std::string name = pyro::ecs::type_name<WorldModelPosition>();
  EXPECT_TRUE(name.size() >= 20 && name.substr(name.size() - 20) == "::WorldModelPosition") << name;
  EXPECT_EQ(pyro::ecs::type_name<int>(), "int");
  EXPECT_EQ(pyro::ecs::type_name<int[3]>(), "int [3]");
  EXPECT_NE(pyro::ecs::type_id<WorldModelPosition>(), pyro::ecs::type_id<WorldModelVelocity>());
  EXPECT_EQ(pyro::ecs::type_id<WorldModelPosition>(), pyro::ecs::type_id<const WorldModelPosition&>());
}

TEST(World, EachBothSignaturesAndGroupOrder) {
  World w;
  std::vector<Entity> es;
  for (int i = 0; i < 10; ++i) {
    es.push_back(w.create());
    w.emplace<WorldModelPosition>(es.back(), float(i), 0.0f, 0.0f);
    if (i % 2 == 0) w.emplace<WorldModelVelocity>(es.back(), 1.0f, 2.0f, 3.0f);
  }
  w.group<WorldModelVelocity, WorldModelPosition>();
  EXPECT_EQ((w.group_size<WorldModelPosition, WorldModelVelocity>()), 5u);
  EXPECT_THROW(w.group_size<WorldModelPosition>(), std::logic_error);
  // Members are packed at the front of both pools.
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(w.pool<WorldModelPosition>()->entities()[i], w.pool<WorldModelVelocity>()->entities()[i]);
    EXPECT_EQ(int(w.pool<WorldModelPosition>()->data()[i].x) % 2, 0);
  }
  w.each<WorldModelPosition, WorldModelVelocity>([](WorldModelPosition& p, const WorldModelVelocity& v) { p.x += v.x * 10.0f; });
  float sum = 0;
  int visits = 0;
  w.each<WorldModelVelocity, WorldModelPosition>([&](Entity e, WorldModelVelocity&, WorldModelPosition& p) {
    sum += p.x;
    ++visits;
    EXPECT_EQ(&p, &w.get<WorldModelPosition>(e));
  });
  EXPECT_EQ(visits, 5);
  EXPECT_EQ(sum, 0 + 2 + 4 + 6 + 8 + 50.0f);
  EXPECT_EQ(w.count<WorldModelPosition>(), 10u);
  EXPECT_EQ(w.count<Settings>(), 0u);
  int none = 0;
  w.each<Settings>([&](Settings&) { ++none; });
  EXPECT_EQ(none, 0);
}

TEST(World, GroupOwnershipIsExclusive) {
  World w;
  w.group<WorldModelPosition, WorldModelVelocity>();
  EXPECT_NO_THROW((w.group<WorldModelVelocity, WorldModelPosition>()));
  EXPECT_THROW(w.group<WorldModelPosition>(), std::logic_error);
  EXPECT_THROW((w.group<WorldModelVelocity, Settings>()), std::logic_error);
  EXPECT_NO_THROW(w.group<Settings>());
}

TEST(World, RefusesStructuralChangeWhileIterating) {
  World w;
  const Entity a = w.create();
  const Entity b = w.create();
  w.emplace<WorldModelPosition>(a);
  w.emplace<WorldModelPosition>(b);
  w.emplace<WorldModelVelocity>(b);
  w.group<WorldModelPosition, WorldModelVelocity>();
  EXPECT_THROW(w.each<WorldModelPosition>([&](Entity e, WorldModelPosition&) { w.destroy(e); }), std::logic_error);
  // WorldModelVelocity shares a group with WorldModelPosition, so adding one would repack WorldModelPosition's pool.
  EXPECT_THROW(w.each<WorldModelPosition>([&](WorldModelPosition&) { w.emplace<WorldModelVelocity>(a); }), std::logic_error);
  EXPECT_TRUE(w.alive(a));
  EXPECT_TRUE(w.alive(b));
  EXPECT_FALSE(w.has<WorldModelVelocity>(a));
  // The lock is released even though f threw; now the change is allowed.
  w.emplace<WorldModelVelocity>(a);
  EXPECT_EQ((w.group_size<WorldModelPosition, WorldModelVelocity>()), 2u);
  w.each<WorldModelVelocity>([&](Entity e, WorldModelVelocity&) {  // other pools are free
    if (e == a) w.emplace<Settings>(a);
  });
  EXPECT_TRUE(w.has<Settings>(a));
}

TEST(World, Resources) {
  World w;
  EXPECT_FALSE(w.has_resource<Settings>());
  EXPECT_EQ(w.try_resource<Settings>(), nullptr);
  try {
    w.resource<Settings>();
    FAIL() << "missing resource must throw";
  } catch (const std::logic_error& err) {
    EXPECT_NE(std::string(err.what()).find("Settings"), std::string::npos) << err.what();
  }
  Settings& s = w.set_resource<Settings>(7);
  EXPECT_EQ(&s, &w.resource<Settings>());
  EXPECT_EQ(w.resource<Settings>().quality, 7);
  w.set_resource<Settings>();  // replaces
  EXPECT_EQ(w.resource<Settings>().quality, 3);
  const World& cw = w;
  EXPECT_TRUE(cw.has_resource<Settings>());
  EXPECT_EQ(cw.resource<Settings>().quality, 3);
  w.remove_resource<Settings>();
  EXPECT_FALSE(w.has_resource<Settings>());
}

}  // namespace
