// The emitter system on hand-built worlds: rate with fractional carry, births within the step, bursts, budgets,
// shapes and distributions, determinism from seeds, prewarm.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "components/emitter.h"
#include "components/frame_clock.h"
#include "components/particle_dynamics.h"
#include "components/particle_set.h"
#include "components/simulation_environment.h"
#include "engine/ecs/world.h"
#include "engine/math/value_noise.h"
#include "systems/animation/particle_animation_system.h"
#include "systems/animation/particle_prewarm.h"
#include "systems/emitter/emitter_sampling.h"
#include "systems/emitter/emitter_system.h"

namespace pyro {
namespace {

Emitter make_emitter(uint64_t seed = 11) {
  Emitter e;
  e.seed = seed;
  e.rng = Rng(seed);
  e.budget = 1000;
  return e;
}

TEST(EmitterSystem, RateCarriesFractionsExactly) {
  Emitter e = make_emitter();
  e.rate = 7.5f;
  ParticlePool pool(1000);
  uint64_t room = 1000;
  const double dt = 1.0 / 30.0;
  uint64_t total = 0;
  for (int f = 0; f <= 30; ++f) total += emit_until(e, pool, f * dt, room);
  EXPECT_EQ(total, 7u);  // floor(7.5 · 1 s)
  for (int f = 31; f <= 60; ++f) total += emit_until(e, pool, f * dt, room);
  EXPECT_EQ(total, 15u);  // floor(7.5 · 2 s): the half carried over
  EXPECT_EQ(pool.size(), 15u);
}

// A stream's n-th particle is born at n / rate: three born in a step of 0.1 s at 30 a second, at
// 1/30, 2/30 and 3/30 s, are 2/30, 1/30 and 0 s old; the next step (no forces: constant velocity)
// moves each over its age and the step, so they stand 1/30 s of flight apart, not together.
TEST(EmitterSystem, StreamParticlesCatchUpFromTheirBirthInTheStep) {
  Emitter e = make_emitter();
  e.rate = 30.0f;
  e.speed = Distribution::constant(1.5f);
  ParticlePool pool(10);
  uint64_t room = 10;
  ASSERT_EQ(emit_until(e, pool, 0.1, room), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(pool.age[size_t(i)], (2 - i) / 30.0, 1e-6) << "particle " << i;
  ParticleDynamics still;
  still.drag = 0.0f;
  still.gravity_scale = 0.0f;
  still.buoyancy = 0.0f;
  still.turbulence = 0.0f;
  SimulationEnvironment env;
  env.gravity = glm::vec3(0.0f);
  animate_particles(pool, still, env, 0.1f, 0.1);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(pool.py[size_t(i)], 1.5 * (0.1 + (2 - i) / 30.0), 1e-5) << "particle " << i;
    EXPECT_NEAR(pool.age[size_t(i)], 0.1 + (2 - i) / 30.0, 1e-6);
  }
}

// The share of `pool`'s particles born where the pattern's noise reaches its threshold.
double share_on_pattern(const Emitter& e, const ParticlePool& pool) {
  int on = 0;
  for (size_t i = 0; i < pool.size(); ++i) {
    const glm::vec3 p(pool.px[i], pool.py[i], pool.pz[i]);
    on += value_noise(p * e.pattern.frequency, e.seed ^ 0x5bd1e995u) >= e.pattern.threshold;
  }
  return double(on) / double(pool.size());
}

// A pattern gathers births where its noise is high: with up to 16 draws a birth nearly always
// lands there, where without the pattern a share near the noise's own area falls there.
TEST(EmitterSystem, APatternGathersBirthsWhereItsNoiseIsHigh) {
  Emitter e = make_emitter();
  e.shape = EmitterShape::disc;
  e.radius = 1.0f;
  e.rate = 1000.0f;
  e.pattern = {3.0f, 0.0f, 0.3f};
  ParticlePool patterned(1000), plain(1000);
  uint64_t room = 2000;
  ASSERT_EQ(emit_until(e, patterned, 1.0, room), 1000u);
  Emitter f = make_emitter();
  f.shape = EmitterShape::disc;
  f.radius = 1.0f;
  f.rate = 1000.0f;
  ASSERT_EQ(emit_until(f, plain, 1.0, room), 1000u);
  f.pattern = e.pattern;  // measured against the same noise
  EXPECT_GT(share_on_pattern(e, patterned), 0.97);
  EXPECT_LT(share_on_pattern(f, plain), 0.5);
}

TEST(EmitterSystem, RateRespectsStartAndDuration) {
  Emitter e = make_emitter();
  e.rate = 10.0f;
  e.start = 1.0f;
  e.duration = 0.5f;
  ParticlePool pool(100);
  uint64_t room = 100;
  EXPECT_EQ(emit_until(e, pool, 0.9, room), 0u);
  EXPECT_EQ(emit_until(e, pool, 3.0, room), 5u);
}

TEST(EmitterSystem, BurstsFireOnceAtTheirTime) {
  Emitter e = make_emitter();
  e.bursts = {{0.0f, 3}, {0.5f, 10}};
  ParticlePool pool(100);
  uint64_t room = 100;
  EXPECT_EQ(emit_until(e, pool, 0.0, room), 3u);
  EXPECT_EQ(emit_until(e, pool, 0.49, room), 0u);
  EXPECT_EQ(emit_until(e, pool, 0.51, room), 10u);
  EXPECT_EQ(emit_until(e, pool, 5.0, room), 0u);
}

TEST(EmitterSystem, BudgetsCountRefusalsAndNeverGrowThePool) {
  Emitter e = make_emitter();
  e.budget = 5;
  e.bursts = {{0.0f, 12}};
  ParticlePool pool(5);
  uint64_t room = 100;
  EXPECT_EQ(emit_until(e, pool, 0.0, room), 5u);
  EXPECT_EQ(e.over_budget, 7u);
  EXPECT_EQ(pool.capacity(), 5u);
  // Scene budget: room for 2 more in the scene.
  Emitter f = make_emitter(12);
  f.bursts = {{0.0f, 4}};
  ParticlePool pool2(10);
  uint64_t scene_room = 2, scene_refused = 0;
  EXPECT_EQ(emit_until(f, pool2, 0.0, scene_room, &scene_refused), 2u);
  EXPECT_EQ(f.over_budget, 2u);
  EXPECT_EQ(scene_refused, 2u);
}

TEST(EmitterSystem, ShapesAndConesHoldTheirParticles) {
  Rng rng(5);
  Emitter e = make_emitter();
  e.position = {1.0f, 2.0f, 3.0f};
  e.radius = 2.0f;
  e.shape = EmitterShape::sphere;
  e.surface = true;
  for (int i = 0; i < 500; ++i) EXPECT_NEAR(glm::length(sample_shape(e, rng) - e.position), 2.0f, 1e-5f);
  e.surface = false;
  double mean_r3 = 0.0;
  for (int i = 0; i < 4000; ++i) {
    const float r = glm::length(sample_shape(e, rng) - e.position);
    EXPECT_LE(r, 2.0f + 1e-5f);
    mean_r3 += std::pow(r / 2.0, 3.0) / 4000.0;
  }
  EXPECT_NEAR(mean_r3, 0.5, 0.03);  // uniform in volume: (r/R)³ is uniform
  e.shape = EmitterShape::disc;
  e.axis = {0.0f, 0.0f, 1.0f};
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 p = sample_shape(e, rng) - e.position;
    EXPECT_NEAR(p.z, 0.0f, 1e-5f);
    EXPECT_LE(glm::length(p), 2.0f + 1e-5f);
  }
  e.shape = EmitterShape::box;
  e.half_extent = {0.5f, 1.0f, 2.0f};
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 p = sample_shape(e, rng) - e.position;
    EXPECT_LE(std::abs(p.x), 0.5f);
    EXPECT_LE(std::abs(p.y), 1.0f);
    EXPECT_LE(std::abs(p.z), 2.0f);
  }
  const glm::vec3 axis = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
  double mean_cos = 0.0;
  for (int i = 0; i < 4000; ++i) {
    const glm::vec3 d = sample_cone(axis, 30.0f, rng);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
    EXPECT_GE(glm::dot(d, axis), std::cos(30.0f * std::numbers::pi_v<float> / 180.0f) - 1e-5f);
    mean_cos += glm::dot(d, axis) / 4000.0;
  }
  EXPECT_NEAR(mean_cos, (1.0 + std::cos(std::numbers::pi / 6.0)) / 2.0, 3e-3);  // cos θ uniform
}

TEST(EmitterSystem, DistributionsStayInRange) {
  Rng rng(9);
  const Distribution n = Distribution::normal(2500.0f, 400.0f, 2000.0f, 3200.0f);
  const Distribution u = Distribution::uniform(1.0f, 3.0f);
  double sum = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const float a = sample_distribution(n, rng), b = sample_distribution(u, rng);
    EXPECT_GE(a, 2000.0f);
    EXPECT_LE(a, 3200.0f);
    EXPECT_GE(b, 1.0f);
    EXPECT_LT(b, 3.0f);
    sum += b;
  }
  EXPECT_NEAR(sum / 20000.0, 2.0, 0.02);
  EXPECT_EQ(sample_distribution(Distribution::constant(4.0f), rng), 4.0f);
}

// A world with one emitter entity and the resources the systems read.
struct TestWorld {
  ecs::World world;
  explicit TestWorld(uint64_t seed, uint32_t budget = 1000) {
    world.set_resource<FrameClock>(FrameClock{0, 0.05f});
    SimulationEnvironment env;
    env.ground = true;
    world.set_resource<SimulationEnvironment>(env);
    const ecs::Entity en = world.create();
    Emitter e = make_emitter(seed);
    e.shape = EmitterShape::sphere;
    e.radius = 0.5f;
    e.position = {0.0f, 1.0f, 0.0f};
    e.rate = 40.0f;
    e.bursts = {{0.0f, 20}};
    e.radial = true;
    e.speed = Distribution::uniform(2.0f, 6.0f);
    e.lifetime = Distribution::uniform(0.5f, 2.0f);
    e.temperature = Distribution::normal(2800.0f, 200.0f, 2500.0f, 3200.0f);
    e.medium = ParticleMedium::fire;
    e.budget = budget;
    world.emplace<Emitter>(en, e);
    ParticleDynamics d;
    d.drag = 2.0f;
    d.buoyancy = 0.01f;
    d.cooling = 1.5f;
    d.smoke_below = 1200.0f;
    d.turbulence = 1.0f;
    world.emplace<ParticleDynamics>(en, d);
    world.emplace<ParticleSet>(en, ParticleSet{ParticlePool(budget)});
  }
  void frame() {
    emitter_system().run(world);
    animation_system().run(world);
    world.resource<FrameClock>().frame += 1;
  }
  const ParticlePool& pool() {
    const ParticlePool* p = nullptr;
    world.each<ParticleSet>([&](ParticleSet& s) { p = &s.pool; });
    return *p;
  }
};

bool same_pools(const ParticlePool& a, const ParticlePool& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a.px[i] != b.px[i] || a.py[i] != b.py[i] || a.vz[i] != b.vz[i] || a.temperature[i] != b.temperature[i] ||
        a.id[i] != b.id[i] || a.medium[i] != b.medium[i])
      return false;
  return true;
}

TEST(EmitterSystem, SameSeedSameParticlesOtherSeedOthers) {
  TestWorld a(3), b(3), c(4);
  for (int f = 0; f < 40; ++f) a.frame(), b.frame(), c.frame();
  EXPECT_GT(a.pool().size(), 20u);
  EXPECT_TRUE(same_pools(a.pool(), b.pool()));
  EXPECT_FALSE(same_pools(a.pool(), c.pool()));
}

TEST(EmitterSystem, PrewarmEqualsRunningTheSteps) {
  TestWorld ran(3), warmed(3);
  for (int f = 0; f < 30; ++f) ran.frame();  // steps 0..29
  prewarm_particles(warmed.world, 25);       // steps 0..24
  for (int f = 0; f < 5; ++f) warmed.frame();  // steps 25..29
  EXPECT_TRUE(same_pools(ran.pool(), warmed.pool()));
  EXPECT_EQ(warmed.world.resource<FrameClock>().frame, 5u);
}

TEST(EmitterSystem, ParticlesDieAtTheirLifetimeAndSurvivorsKeepOrder) {
  TestWorld w(8);
  for (int f = 0; f < 80; ++f) {
    w.frame();
    const ParticlePool& p = w.pool();
    for (std::size_t i = 0; i < p.size(); ++i) {
      EXPECT_LT(p.age[i], p.lifetime[i]);
      if (i > 0) {
        EXPECT_LT(p.id[i - 1], p.id[i]);  // kill_if keeps spawn order
      }
      EXPECT_GE(p.py[i], 0.0f);                    // the ground holds
    }
  }
  EXPECT_GT(w.pool().next_id(), 150u);  // 20 + 40/s · 4 s spawned, most died
}

}  // namespace
}  // namespace pyro
