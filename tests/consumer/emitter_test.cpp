// A system-level test of an engine system, written as an embedding project would: the engine's
// emitter system run alone (ecs::run_system_once: its setup and run under its declared access)
// on a world built by hand (one sphere emitter and its
// particle set, the clock and the simulation environment), checked against the emitter's
// contract: after scene time t it has spawned floor(rate · (t − start)) particles plus every
// burst due by t, each inside its sphere, with the size it asks for, up to its budget.
#include "components/emitter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <set>

#include "components/frame_clock.h"
#include "components/particle_set.h"
#include "components/simulation_environment.h"
#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"
#include "systems/emitter/emitter_system.h"

namespace {

using namespace pyro;

constexpr float kDt = 1.0f / 30.0f;
const glm::vec3 kCenter{1.0f, 2.0f, -3.0f};
constexpr float kRadius = 0.75f;
constexpr float kRate = 90.0f;      // particles per second
constexpr float kBurstTime = 0.5f;  // seconds
constexpr uint32_t kBurstCount = 25;

struct EmitterWorld {
  ecs::World world;
  ecs::Entity emitter;
  ecs::SystemDesc system = emitter_system();

  explicit EmitterWorld(uint32_t budget) {
    world.set_resource<FrameClock>(FrameClock{0, kDt});
    world.set_resource<SimulationEnvironment>();
    emitter = world.create();
    Emitter e;
    e.shape = EmitterShape::sphere;
    e.position = kCenter;
    e.radius = kRadius;
    e.rate = kRate;
    e.bursts = {{kBurstTime, kBurstCount}};
    e.size = Distribution::constant(0.25f);
    e.budget = budget;
    e.seed = 7;
    e.rng = Rng(e.seed);
    world.emplace<Emitter>(emitter, std::move(e));
    world.emplace<ParticleSet>(emitter, ParticleSet{ParticlePool(budget)});
  }

  // Runs frame f (the clock's frame is set by hand: no other system advances it here).
  void run_frame(uint64_t f) {
    world.resource<FrameClock>().frame = f;
    ecs::run_system_once(system, world);
  }
  const ParticlePool& pool() { return world.get<ParticleSet>(emitter).pool; }
};

// What the emitter owes after scene time t (components/emitter.h).
uint64_t owed(double t) {
  return static_cast<uint64_t>(std::floor(kRate * t)) + (t >= kBurstTime ? kBurstCount : 0);
}

TEST(ConsumerEmitter, SpawnsWhatItsRateAndBurstsOweInsideItsSphere) {
  EmitterWorld w(1000);
  for (uint64_t f = 0; f < 30; ++f) {
    w.run_frame(f);
    const double t = static_cast<double>(f) * kDt;
    ASSERT_EQ(w.pool().size(), owed(t)) << "frame " << f;
  }
  const ParticlePool& p = w.pool();
  std::set<uint32_t> ids;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::vec3 pos{p.px[i], p.py[i], p.pz[i]};
    EXPECT_LE(glm::length(pos - kCenter), kRadius * (1.0f + 1e-5f)) << "particle " << i;
    EXPECT_EQ(p.radius[i], 0.25f);
    ids.insert(p.id[i]);
  }
  EXPECT_EQ(ids.size(), p.size()) << "particle ids are unique";
  // The sphere is filled, not a point: the particles spread over most of its radius.
  float farthest = 0.0f;
  for (std::size_t i = 0; i < p.size(); ++i)
    farthest = std::max(farthest, glm::length(glm::vec3{p.px[i], p.py[i], p.pz[i]} - kCenter));
  EXPECT_GT(farthest, 0.8f * kRadius);
}

TEST(ConsumerEmitter, StopsAtItsBudgetAndCountsWhatItRefused) {
  constexpr uint32_t budget = 40;
  EmitterWorld w(budget);
  for (uint64_t f = 0; f < 30; ++f) w.run_frame(f);
  const double t = 29.0 * kDt;
  EXPECT_EQ(w.pool().size(), budget);
  EXPECT_EQ(w.world.get<Emitter>(w.emitter).over_budget, owed(t) - budget);
}

}  // namespace
