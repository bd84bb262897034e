#include "systems/animation/particle_integrator.h"

namespace pyro {

void step_exponential(ParticleState& s, const ConstantForces& f, double dt) {
  const double e = std::exp(-f.drag * dt);
  const double p1 = exp_phi1(f.drag, dt), p2 = exp_phi2(f.drag, dt);
  const glm::dvec3 forcing = f.acceleration + f.drag * f.wind;
  s.x += s.v * p1 + forcing * p2;
  s.v = s.v * e + forcing * p1;
  s.temperature = f.ambient + (s.temperature - f.ambient) * std::exp(-f.cooling * dt);
}

void step_explicit_euler(ParticleState& s, const ConstantForces& f, double dt) {
  const glm::dvec3 a = f.acceleration - f.drag * (s.v - f.wind);
  s.x += s.v * dt;
  s.v += a * dt;
  s.temperature += -f.cooling * (s.temperature - f.ambient) * dt;
}

ParticleState run_steps(IntegratorKind kind, ParticleState s, const ConstantForces& f, double dt, int n) {
  for (int i = 0; i < n; ++i) {
    if (kind == IntegratorKind::engine) step_exponential(s, f, dt);
    else step_explicit_euler(s, f, dt);
  }
  return s;
}

ParticleState exact_solution(const ParticleState& s0, const ConstantForces& f, double t) {
  // Textbook form, written independently of the step: with terminal velocity
  // v_inf = w + a / k, v(t) = v_inf + (v0 − v_inf) e^{−kt} and
  // x(t) = x0 + v_inf t + (v0 − v_inf)(1 − e^{−kt}) / k; ballistic when k = 0.
  ParticleState s = s0;
  if (f.drag == 0.0) {
    s.x = s0.x + s0.v * t + 0.5 * f.acceleration * t * t;
    s.v = s0.v + f.acceleration * t;
  } else {
    const glm::dvec3 v_inf = f.wind + f.acceleration / f.drag;
    const double e = std::exp(-f.drag * t);
    s.v = v_inf + (s0.v - v_inf) * e;
    s.x = s0.x + v_inf * t + (s0.v - v_inf) * ((1.0 - e) / f.drag);
  }
  s.temperature = f.ambient + (s0.temperature - f.ambient) * std::exp(-f.cooling * t);
  return s;
}

}  // namespace pyro
