// The animation's integrators against the closed-form solution of linear drag and cooling:
// explicit Euler fails where k·dt > 2; the engine's exponential integrator does not.
#include <gtest/gtest.h>

#include <cmath>

#include "systems/animation/particle_integrator.h"

namespace pyro {
namespace {

// Independent closed forms, written out here: dv/dt = a − k (v − w), dT/dt = −k_c (T − T_a).
double v_exact(double v0, double a, double w, double k, double t) {
  const double vi = w + a / k;
  return vi + (v0 - vi) * std::exp(-k * t);
}
double x_exact(double x0, double v0, double a, double w, double k, double t) {
  const double vi = w + a / k;
  return x0 + vi * t + (v0 - vi) * (1.0 - std::exp(-k * t)) / k;
}

ConstantForces stiff() {
  ConstantForces f;
  f.acceleration = {0.0, -9.81, 0.0};
  f.wind = {3.0, 0.0, -1.0};
  f.drag = 50.0;     // 1/s: at dt = 1/20, k·dt = 2.5
  f.cooling = 60.0;  // 1/s: k_c·dt = 3
  f.ambient = 293.0;
  return f;
}

TEST(ParticleIntegrator, ExplicitEulerBlowsUpOnStiffDragTheEngineDoesNot) {
  const ConstantForces f = stiff();
  const ParticleState s0{{0.0, 1.0, 0.0}, {10.0, 20.0, 0.0}, 3000.0};
  const double dt = 1.0 / 20.0;
  const int n = 40;  // 2 s
  const ParticleState euler = run_steps(IntegratorKind::explicit_euler, s0, f, dt, n);
  const ParticleState engine = run_steps(IntegratorKind::engine, s0, f, dt, n);
  const double t = dt * n;
  // Euler: v − v_inf is multiplied by (1 − k dt) = −1.5 per step: |−1.5|^40 ≈ 1e7.
  EXPECT_GT(std::abs(euler.v.x - v_exact(10.0, 0.0, 3.0, 50.0, t)), 1e5);
  EXPECT_GT(std::abs(euler.temperature - 293.0), 1e6);  // (1 − 3)^40 ≈ 1e12
  // The engine stays on the closed form.
  EXPECT_NEAR(engine.v.x, v_exact(10.0, 0.0, 3.0, 50.0, t), 1e-6);
  EXPECT_NEAR(engine.v.y, v_exact(20.0, -9.81, 0.0, 50.0, t), 1e-6);
  EXPECT_NEAR(engine.x.x, x_exact(0.0, 10.0, 0.0, 3.0, 50.0, t), 1e-6);
  EXPECT_NEAR(engine.x.y, x_exact(1.0, 20.0, -9.81, 0.0, 50.0, t), 1e-6);
  EXPECT_NEAR(engine.temperature, 293.0 + (3000.0 - 293.0) * std::exp(-60.0 * t), 1e-6);
}

TEST(ParticleIntegrator, EngineIsExactForAnyStepAndEulerOscillatesPastOne) {
  const ConstantForces f = stiff();
  const ParticleState s0{{0.0, 0.0, 0.0}, {0.0, 5.0, 0.0}, 1500.0};
  for (double dt : {0.001, 0.01, 0.03, 0.05, 0.1, 0.5}) {
    const int n = static_cast<int>(std::lround(1.0 / dt));
    const ParticleState a = run_steps(IntegratorKind::engine, s0, f, dt, n);
    const ParticleState ex = exact_solution(s0, f, dt * n);
    EXPECT_NEAR(a.v.y, v_exact(5.0, -9.81, 0.0, 50.0, dt * n), 1e-6) << dt;
    EXPECT_NEAR(a.x.y, ex.x.y, 1e-6) << dt;
    EXPECT_NEAR(a.temperature, ex.temperature, 1e-6) << dt;
  }
  // Euler: one step of dt with 1 < k dt < 2 overshoots the terminal velocity (sign flips).
  ParticleState e = s0;
  ConstantForces g = f;
  g.acceleration = {0.0, 0.0, 0.0};
  g.wind = {0.0, 0.0, 0.0};
  step_explicit_euler(e, g, 0.03);  // k dt = 1.5
  EXPECT_LT(e.v.y, 0.0);
  // ... and stays bounded but accurate only for small k dt.
  const ParticleState small = run_steps(IntegratorKind::explicit_euler, s0, f, 1e-4, 10000);
  EXPECT_NEAR(small.v.y, v_exact(5.0, -9.81, 0.0, 50.0, 1.0), 1e-3);
}

TEST(ParticleIntegrator, NoDragIsBallistic) {
  ConstantForces f;
  f.acceleration = {0.0, -9.81, 0.0};
  const ParticleState s0{{0.0, 0.0, 0.0}, {2.0, 10.0, 0.0}, 293.0};
  const ParticleState s = run_steps(IntegratorKind::engine, s0, f, 1.0 / 30.0, 30);
  EXPECT_NEAR(s.x.y, 10.0 - 0.5 * 9.81, 1e-9);
  EXPECT_NEAR(s.v.y, 10.0 - 9.81, 1e-9);
  EXPECT_NEAR(s.x.x, 2.0, 1e-12);
}

TEST(ParticleIntegrator, PhiFunctionsAreSmoothThroughSmallK) {
  const double dt = 0.1;
  // Against expm1 forms (no cancellation) away from 0, and across the series switch at kΔt = 1e-3.
  for (double k : {1e-9, 1e-5, 0.0099, 0.0101, 1.0, 30.0})
    EXPECT_NEAR(exp_phi1(k, dt) / dt, -std::expm1(-k * dt) / (k * dt), 1e-12) << k;
  for (double k : {0.5, 1.0, 30.0})
    EXPECT_NEAR(exp_phi2(k, dt), (k * dt + std::expm1(-k * dt)) / (k * k), 1e-12) << k;
  const double below = exp_phi2(0.0099999, dt), above = exp_phi2(0.0100001, dt);
  EXPECT_NEAR(below / (dt * dt), above / (dt * dt), 1e-8);
  EXPECT_NEAR(exp_phi2(0.0, dt), 0.005, 1e-15);
  EXPECT_NEAR(exp_phi1(0.0, dt), 0.1, 1e-15);
}

}  // namespace
}  // namespace pyro
