#pragma once
// Time integration of one particle under
//   dx/dt = v,   dv/dt = a − k (v − w),   dT/dt = −k_c (T − T_amb)
// with a (gravity, buoyancy), w (wind + turbulence), k, k_c, T_amb held constant over a step.
//
// The engine's method is the exponential integrator (exponential time differencing, e.g.
// Hochbruck & Ostermann 2010, "Exponential integrators", Acta Numerica): the linear, stiff parts
// (drag, cooling) are integrated exactly,
//   v₁ = v e^{−k Δt} + (a + k w) φ₁,        φ₁ = (1 − e^{−k Δt}) / k
//   x₁ = x + v φ₁ + (a + k w) φ₂,            φ₂ = (Δt − φ₁) / k
//   T₁ = T_amb + (T − T_amb) e^{−k_c Δt}
// so for constant forces it is the closed-form solution at every Δt (stable for any k Δt), and
// with k → 0 it becomes x₁ = x + v Δt + a Δt²/2, v₁ = v + a Δt. Forces that vary along the path
// (buoyancy through T, turbulence through x) are frozen at the step's start.
//
// Explicit Euler, for comparison, multiplies v − w − a/k by (1 − k Δt) each step: it oscillates
// once k Δt > 1 and blows up once k Δt > 2.
#include <cmath>

#include <glm/vec3.hpp>

namespace pyro {

// φ₁(k, Δt) = (1 − e^{−kΔt}) / k and φ₂(k, Δt) = (Δt − φ₁) / k, accurate as k → 0.
template <class T>
T exp_phi1(T k, T dt) {
  const T z = k * dt;
  if (std::abs(z) < T(1e-3)) return dt * (T(1) - z / T(2) + z * z / T(6) - z * z * z / T(24));
  return -std::expm1(-z) / k;
}
template <class T>
T exp_phi2(T k, T dt) {
  const T z = k * dt;
  if (std::abs(z) < T(1e-3)) return dt * dt * (T(0.5) - z / T(6) + z * z / T(24) - z * z * z / T(120));
  return (z + std::expm1(-z)) / (k * k);
}

enum class IntegratorKind { engine, explicit_euler };

struct ParticleState {
  glm::dvec3 x{0.0}, v{0.0};
  double temperature = 0.0;
};

struct ConstantForces {
  glm::dvec3 acceleration{0.0};  // gravity + buoyancy, held constant
  glm::dvec3 wind{0.0};
  double drag = 0.0;             // k
  double cooling = 0.0;          // k_c
  double ambient = 293.0;        // T_amb
};

void step_exponential(ParticleState& s, const ConstantForces& f, double dt);
void step_explicit_euler(ParticleState& s, const ConstantForces& f, double dt);

// n steps of dt with the chosen method, for charts of error against Δt.
ParticleState run_steps(IntegratorKind kind, ParticleState s, const ConstantForces& f, double dt, int n);

// The exact solution at time t (the closed form of the linear ODEs above).
ParticleState exact_solution(const ParticleState& s0, const ConstantForces& f, double t);

}  // namespace pyro
