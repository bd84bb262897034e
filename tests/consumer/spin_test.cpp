// The consumer's own system on a hand-built world: spin_system in a Schedule turns a set's
// particles about the Spin's vertical axis by rate · dt per frame after frame 0, keeping each
// particle's height and distance to the axis.
#include "spin/spin.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "components/frame_clock.h"
#include "components/particle_set.h"
#include "engine/core/rng.h"
#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"
#include "spin/spin_system.h"

namespace {

using namespace pyro;

TEST(ConsumerSpin, TurnsParticlesAboutTheVerticalAxisAtItsRate) {
  constexpr float dt = 1.0f / 24.0f;
  const spin::Spin s{{0.5f, 0.0f, -1.0f}, std::numbers::pi_v<float> / 3.0f};  // 60 deg/s
  ecs::World world;
  world.set_resource<FrameClock>(FrameClock{0, dt});
  const ecs::Entity e = world.create();
  ParticlePool pool(64);
  Rng rng(3);
  for (int i = 0; i < 64; ++i)
    pool.spawn({.position = {rng.uniform(-2.0f, 2.0f), rng.uniform(0.0f, 3.0f),
                             rng.uniform(-2.0f, 2.0f)}});
  const ParticlePool start = pool;
  world.emplace<ParticleSet>(e, ParticleSet{std::move(pool)});
  world.emplace<spin::Spin>(e, s);
  ecs::Schedule schedule;
  schedule.add(spin::spin_system());
  schedule.setup(world);
  constexpr int frames = 13;  // frame 0 leaves the state as built: 12 turns of rate · dt
  for (int f = 0; f < frames; ++f) {
    world.resource<FrameClock>().frame = static_cast<uint64_t>(f);
    schedule.run_frame(world);
  }
  const float turned = s.radians_per_second * dt * (frames - 1);
  const ParticlePool& p = world.get<ParticleSet>(e).pool;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const float x0 = start.px[i] - s.center.x, z0 = start.pz[i] - s.center.z;
    const float x = p.px[i] - s.center.x, z = p.pz[i] - s.center.z;
    EXPECT_EQ(p.py[i], start.py[i]);
    EXPECT_NEAR(std::hypot(x, z), std::hypot(x0, z0), 1e-4f);
    // Counter-clockwise seen from +y: the angle atan2(-z, x) grows by `turned`.
    float d = std::atan2(-z, x) - std::atan2(-z0, x0) - turned;
    d = std::remainder(d, 2.0f * std::numbers::pi_v<float>);
    EXPECT_NEAR(d, 0.0f, 1e-4f) << "particle " << i;
  }
}

}  // namespace
