// The animation system's physics on single particles against closed forms: cooling and
// fire-to-smoke, buoyancy, drag toward the wind, collisions, curves over life.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "components/particle_dynamics.h"
#include "components/particle_medium.h"
#include "components/simulation_environment.h"
#include "engine/particles/particle_pool.h"
#include "systems/animation/particle_animation_system.h"

namespace pyro {
namespace {

SimulationEnvironment still_air() {
  SimulationEnvironment env;
  env.gravity = {0.0f, 0.0f, 0.0f};
  env.ambient_temperature = 300.0f;
  return env;
}

TEST(ParticleAnimation, NewtonCoolingAndFireTurnsToSmoke) {
  ParticlePool p(4);
  ParticleInit in;
  in.temperature = 3000.0f;
  in.lifetime = 100.0f;
  in.medium = static_cast<uint8_t>(ParticleMedium::fire);
  p.spawn(in);
  ParticleDynamics d;
  d.cooling = 0.8f;
  d.smoke_below = 1000.0f;
  const SimulationEnvironment env = still_air();
  const float dt = 0.1f;
  // T(t) = 300 + 2700 e^{−0.8 t} crosses 1000 K at t = ln(2700/700)/0.8 = 1.687 s.
  for (int s = 1; s <= 30; ++s) {
    animate_particles(p, d, env, dt, 0.0);
    const double t = s * dt;
    EXPECT_NEAR(p.temperature[0], 300.0 + 2700.0 * std::exp(-0.8 * t), 2e-2) << t;
    const bool smoke = p.medium[0] == static_cast<uint8_t>(ParticleMedium::smoke);
    EXPECT_EQ(smoke, t > std::log(2700.0 / 700.0) / 0.8) << t;
  }
}

TEST(ParticleAnimation, BuoyancyLiftsHotGas) {
  ParticlePool p(1);
  ParticleInit in;
  in.temperature = 1300.0f;
  in.lifetime = 100.0f;
  p.spawn(in);
  ParticleDynamics d;
  d.buoyancy = 0.002f;  // a = 0.002 · 1000 = 2 m/s² up while T stays (no cooling)
  const SimulationEnvironment env = still_air();
  for (int s = 0; s < 10; ++s) animate_particles(p, d, env, 0.1f, 0.0);
  EXPECT_NEAR(p.vy[0], 2.0f, 1e-4f);
  EXPECT_NEAR(p.py[0], 1.0f, 1e-4f);  // a t² / 2
}

TEST(ParticleAnimation, DragReachesTheWindAtLargeSteps) {
  ParticlePool p(1);
  ParticleInit in;
  in.velocity = {0.0f, 0.0f, 20.0f};
  in.lifetime = 100.0f;
  p.spawn(in);
  ParticleDynamics d;
  d.drag = 40.0f;  // k dt = 4 at 10 fps: explicit Euler would diverge
  SimulationEnvironment env = still_air();
  env.wind = {3.0f, 0.0f, 0.0f};
  for (int s = 0; s < 5; ++s) animate_particles(p, d, env, 0.1f, 0.0);
  EXPECT_NEAR(p.vx[0], 3.0f * (1.0f - std::exp(-40.0f * 0.5f)), 1e-5f);
  EXPECT_NEAR(p.vz[0], 20.0f * std::exp(-40.0f * 0.5f), 1e-5f);
}

TEST(ParticleAnimation, CollisionsKeepParticlesOutside) {
  SimulationEnvironment env;
  env.ground = true;
  env.spheres = {{{0.0f, 1.0f, 0.0f}, 0.5f}};
  env.boxes = {{{2.0f, 0.0f, -1.0f}, {3.0f, 1.0f, 1.0f}}};
  // Ground: bounce with restitution 0.5, friction 0.25.
  glm::vec3 x(0.0f, -0.1f, 5.0f), v(4.0f, -2.0f, 0.0f);
  EXPECT_TRUE(collide_particle(x, v, env, 0.5f, 0.25f));
  EXPECT_EQ(x.y, 0.0f);
  EXPECT_NEAR(v.y, 1.0f, 1e-6f);
  EXPECT_NEAR(v.x, 3.0f, 1e-6f);
  // Sphere: pushed to the surface, normal velocity reflected.
  x = {0.0f, 1.2f, 0.0f};
  v = {0.0f, -1.0f, 0.0f};
  EXPECT_TRUE(collide_particle(x, v, env, 1.0f, 0.0f));
  EXPECT_NEAR(glm::length(x - glm::vec3(0.0f, 1.0f, 0.0f)), 0.5f, 1e-6f);
  EXPECT_NEAR(v.y, 1.0f, 1e-6f);
  // Box: out through the nearest face (x = 2).
  x = {2.1f, 0.5f, 0.0f};
  v = {1.0f, 0.0f, 0.0f};
  EXPECT_TRUE(collide_particle(x, v, env, 0.0f, 0.0f));
  EXPECT_EQ(x.x, 2.0f);
  EXPECT_EQ(v.x, 0.0f);
  // Falling particles never go under the ground.
  ParticlePool p(1);
  ParticleInit in;
  in.position = {0.0f, 3.0f, 5.0f};
  in.lifetime = 100.0f;
  p.spawn(in);
  ParticleDynamics d;
  for (int s = 0; s < 100; ++s) {
    animate_particles(p, d, env, 1.0f / 30.0f, 0.0);
    EXPECT_GE(p.py[0], 0.0f);
  }
}

TEST(ParticleAnimation, CurvesOverLife) {
  ParticlePool p(1);
  ParticleInit in;
  in.radius = 0.5f;
  in.lifetime = 2.0f;
  p.spawn(in);
  ParticleDynamics d;
  d.size.keys = {{0.0f, glm::vec3(1.0f)}, {1.0f, glm::vec3(3.0f)}};
  d.opacity.keys = {{0.0f, glm::vec3(1.0f)}, {0.5f, glm::vec3(1.0f)}, {1.0f, glm::vec3(0.0f)}};
  d.color.keys = {{0.0f, {1.0f, 0.5f, 0.0f}}, {1.0f, {0.2f, 0.2f, 0.2f}}};
  const SimulationEnvironment env = still_air();
  for (int s = 0; s < 15; ++s) animate_particles(p, d, env, 0.1f, 0.0);  // life 0.75
  EXPECT_NEAR(p.radius[0], 0.5f * 2.5f, 1e-5f);
  EXPECT_NEAR(p.opacity[0], 0.5f, 1e-5f);
  EXPECT_NEAR(p.g[0], 0.5f + 0.75f * (0.2f - 0.5f), 1e-5f);
  for (int s = 0; s < 5; ++s) animate_particles(p, d, env, 0.1f, 0.0);
  EXPECT_EQ(p.size(), 0u);  // age 2 s = lifetime: removed
}

}  // namespace
}  // namespace pyro
