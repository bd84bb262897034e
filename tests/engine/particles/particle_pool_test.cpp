#include "engine/particles/particle_pool.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <set>
#include <vector>

namespace {

using pyro::ParticleInit;
using pyro::ParticlePool;

// Model particle: the 14 float attributes in declaration order, then the id.
struct Row {
  std::array<float, 14> f;
  uint32_t id;
  bool operator==(const Row&) const = default;
};

Row row_of(const ParticlePool& p, std::size_t i) {
  return Row{{p.px[i], p.py[i], p.pz[i], p.vx[i], p.vy[i], p.vz[i], p.radius[i], p.density[i],
              p.r[i], p.g[i], p.b[i], p.age[i], p.lifetime[i], p.temperature[i]},
             p.id[i]};
}

Row expected_row(const ParticleInit& in, uint32_t id) {
  return Row{{in.position.x, in.position.y, in.position.z, in.velocity.x, in.velocity.y,
              in.velocity.z, in.radius, in.density, in.color.x, in.color.y, in.color.z, 0.0f,
              in.lifetime, in.temperature},
             id};
}

ParticleInit random_init(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-100.0f, 100.0f);
  ParticleInit p;
  p.position = {u(rng), u(rng), u(rng)};
  p.velocity = {u(rng), u(rng), u(rng)};
  p.radius = u(rng);
  p.density = u(rng);
  p.color = {u(rng), u(rng), u(rng)};
  p.lifetime = u(rng);
  p.temperature = u(rng);
  return p;
}

std::vector<const void*> data_pointers(const ParticlePool& p) {
  std::vector<const void*> ptrs;
  p.for_each_array([&](const auto& a) { ptrs.push_back(a.data()); });
  return ptrs;
}

void expect_matches(const ParticlePool& pool, const std::vector<Row>& model) {
  ASSERT_EQ(pool.size(), model.size());
  for (std::size_t i = 0; i < model.size(); ++i) ASSERT_EQ(row_of(pool, i), model[i]) << "at " << i;
}

TEST(ParticlePool, SpawnToCapacityThenReject) {
  ParticlePool pool(100);
  EXPECT_EQ(pool.capacity(), 100u);
  EXPECT_TRUE(pool.empty());
  pool.for_each_array([&](const auto& a) { EXPECT_EQ(a.size(), 100u); });
  std::mt19937 rng(11);
  std::vector<Row> model;
  for (std::size_t i = 0; i < 100; ++i) {
    const ParticleInit in = random_init(rng);
    const auto slot = pool.spawn(in);
    ASSERT_TRUE(slot.has_value());
    EXPECT_EQ(*slot, i);
    model.push_back(expected_row(in, uint32_t(i)));
  }
  EXPECT_TRUE(pool.full());
  for (int i = 0; i < 7; ++i) EXPECT_FALSE(pool.spawn(random_init(rng)).has_value());
  EXPECT_EQ(pool.rejected(), 7u);
  expect_matches(pool, model);
  pool.kill(0);
  EXPECT_TRUE(pool.spawn(ParticleInit{}).has_value());
  EXPECT_EQ(pool.rejected(), 7u);
  EXPECT_EQ(pool.id[99], 100u) << "rejected spawns must not consume ids";
  EXPECT_THROW(pool.kill(100), std::out_of_range);

  ParticlePool zero(0);
  EXPECT_TRUE(zero.full());
  EXPECT_FALSE(zero.spawn(ParticleInit{}).has_value());
  EXPECT_EQ(zero.rejected(), 1u);
}

TEST(ParticlePool, DefaultInit) {
  ParticlePool pool(1);
  pool.spawn(ParticleInit{{1, 2, 3}, {4, 5, 6}, 0.5f, 2.0f, {0.1f, 0.2f, 0.3f}});
  EXPECT_EQ(pool.px[0], 1.0f);
  EXPECT_EQ(pool.vz[0], 6.0f);
  EXPECT_EQ(pool.radius[0], 0.5f);
  EXPECT_EQ(pool.b[0], 0.3f);
  EXPECT_TRUE(std::isinf(pool.lifetime[0]));
  EXPECT_EQ(pool.temperature[0], 0.0f);
  EXPECT_EQ(pool.age[0], 0.0f);
}

// Random spawns, kills and kill_ifs against a vector model; all arrays checked each step.
TEST(ParticlePool, KillKeepsEveryOtherParticleIntact) {
  constexpr std::size_t cap = 257;
  ParticlePool pool(cap);
  const auto ptrs = data_pointers(pool);
  std::mt19937 rng(2024);
  std::vector<Row> model;
  std::set<uint32_t> ids_ever;
  uint32_t next_id = 0;
  uint64_t rejected = 0;
  for (int step = 0; step < 20000; ++step) {
    // Alternate filling and draining phases so the pool regularly hits capacity.
    const bool filling = (step / 500) % 2 == 0;
    const int op = std::uniform_int_distribution<int>(0, 99)(rng);
    if (op < (filling ? 80 : 30)) {
      const ParticleInit in = random_init(rng);
      const auto slot = pool.spawn(in);
      if (model.size() == cap) {
        ASSERT_FALSE(slot.has_value());
        ++rejected;
      } else {
        ASSERT_EQ(slot, model.size());
        model.push_back(expected_row(in, next_id));
        ASSERT_TRUE(ids_ever.insert(next_id).second) << "id reused";
        ++next_id;
      }
    } else if (filling || op < 98) {
      if (model.empty()) continue;
      const std::size_t i = std::uniform_int_distribution<std::size_t>(0, model.size() - 1)(rng);
      pool.kill(i);
      model[i] = model.back();  // swap-remove
      model.pop_back();
    } else {
      // Kill particles whose radius is negative: survivors keep their order.
      std::vector<std::size_t> asked;
      const std::size_t killed = pool.kill_if([&](std::size_t i) {
        asked.push_back(i);
        return pool.radius[i] < 0.0f;
      });
      std::vector<Row> survivors;
      for (const Row& r : model)
        if (!(r.f[6] < 0.0f)) survivors.push_back(r);
      ASSERT_EQ(killed, model.size() - survivors.size());
      ASSERT_EQ(asked.size(), model.size());
      for (std::size_t i = 0; i < asked.size(); ++i) ASSERT_EQ(asked[i], i);
      model = survivors;
    }
    expect_matches(pool, model);
    if (::testing::Test::HasFailure()) FAIL() << "step " << step;
    ASSERT_EQ(pool.rejected(), rejected);
    ASSERT_EQ(data_pointers(pool), ptrs) << "an array reallocated";
    std::set<uint32_t> live_ids(pool.id.begin(), pool.id.begin() + long(pool.size()));
    ASSERT_EQ(live_ids.size(), pool.size()) << "ids not unique";
  }
  EXPECT_GT(rejected, 0u);
  pool.clear();
  EXPECT_EQ(pool.size(), 0u);
  EXPECT_EQ(data_pointers(pool), ptrs);
  EXPECT_EQ(*pool.spawn(ParticleInit{}), 0u);
  EXPECT_EQ(pool.id[0], next_id) << "ids keep counting after clear()";
}

}  // namespace
