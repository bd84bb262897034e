// pyro chart integrators: the engine's exponential integrator against explicit Euler
// (systems/animation/particle_integrator.h) on a hot, buoyant particle under strong drag, as the
// step grows, against the exact solution of the ODE.
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "systems/animation/particle_integrator.h"
#include "tools/charts/charts.h"

namespace pyro {

namespace {

// The test problem, as the particle animation system poses it each step
// (systems/animation/particle_animation_system.cpp): acceleration = gravity + buoyancy (T - T_amb)
// along +y, held over the step; drag k towards the wind; Newtonian cooling at rate k_c.
struct BuoyantProblem {
  ParticleState start;
  glm::dvec3 gravity{0.0, -9.81, 0.0};
  glm::dvec3 wind{1.0, 0.0, 0.0};
  double buoyancy = 0.01;  // m/s^2 per kelvin above ambient
  double drag = 10.0;      // k
  double cooling = 1.5;    // k_c
  double ambient = 293.0;
};

ParticleState step_coupled(IntegratorKind kind, ParticleState s, const BuoyantProblem& p, double dt) {
  ConstantForces f;
  f.acceleration = p.gravity + glm::dvec3(0.0, p.buoyancy * (s.temperature - p.ambient), 0.0);
  f.wind = p.wind;
  f.drag = p.drag;
  f.cooling = p.cooling;
  f.ambient = p.ambient;
  if (kind == IntegratorKind::engine)
    step_exponential(s, f, dt);
  else
    step_explicit_euler(s, f, dt);
  return s;
}

// The exact solution (linear ODEs, integrating factor e^{kt}): with D = T0 - T_amb,
//   T(t) = T_amb + D e^{-k_c t},
//   v(t) = v_inf + C e^{-k_c t} + (v0 - v_inf - C) e^{-k t},   v_inf = w + g / k,
//   C = b D / (k - k_c) along y (0 along x, z), k != k_c,
//   x(t) = x0 + v_inf t + C (1 - e^{-k_c t}) / k_c + (v0 - v_inf - C)(1 - e^{-k t}) / k.
ParticleState exact_coupled(const BuoyantProblem& p, double t) {
  const double d = p.start.temperature - p.ambient;
  const glm::dvec3 v_inf = p.wind + p.gravity / p.drag;
  const glm::dvec3 c(0.0, p.buoyancy * d / (p.drag - p.cooling), 0.0);
  const double ek = std::exp(-p.drag * t), ec = std::exp(-p.cooling * t);
  ParticleState s;
  s.temperature = p.ambient + d * ec;
  s.v = v_inf + c * ec + (p.start.v - v_inf - c) * ek;
  s.x = p.start.x + v_inf * t + c * ((1.0 - ec) / p.cooling) + (p.start.v - v_inf - c) * ((1.0 - ek) / p.drag);
  return s;
}

}  // namespace

ChartTable chart_integrators(const IntegratorChartOptions& o) {
  BuoyantProblem p;
  p.drag = o.drag;
  p.start.x = glm::dvec3(0.0);
  p.start.v = glm::dvec3(2.0, 8.0, 0.0);
  p.start.temperature = 1800.0;
  const ParticleState exact = exact_coupled(p, o.horizon);
  const double travel = glm::length(exact.x - p.start.x);

  ChartTable t;
  t.name = "integrators";
  t.title = "Particle integrators: exponential (engine) vs explicit Euler, k = " +
            std::to_string(o.drag).substr(0, 5) + "/s";
  t.x_label = "us per particle to simulate " + std::to_string(o.horizon).substr(0, 4) + " s";
  t.y_label = "position error at the end (m)";
  t.ground_truth =
      "the exact solution of the ODEs (drag, buoyancy from Newtonian cooling), closed form in "
      "tools/charts/chart_integrators.cpp; not the CPU reference renderer";
  t.notes = {"problem: x0 = 0, v0 = (2, 8, 0) m/s, T0 = 1800 K, T_amb = 293 K, gravity 9.81, "
             "wind (1, 0, 0), buoyancy 0.01 m/s^2/K, cooling 1.5/s; buoyancy is held over each "
             "step, as in the particle animation system",
             "blew_up: 1 when the error exceeds the distance travelled (" + std::to_string(travel) +
                 " m) or is not finite; explicit Euler is unstable for k dt > 2; blown-up settings are "
                 "never on the Pareto front"};
  t.extra_columns = {"dt", "steps", "k_dt", "blew_up"};
  nlohmann::json blowup = nlohmann::json::object();
  for (IntegratorKind kind : {IntegratorKind::engine, IntegratorKind::explicit_euler}) {
    const std::string name = kind == IntegratorKind::engine ? "exponential" : "explicit Euler";
    double first_blowup = std::numeric_limits<double>::quiet_NaN();
    for (double dt : o.steps) {
      const int n = std::max(1, static_cast<int>(std::lround(o.horizon / dt)));
      const double step = o.horizon / n;
      std::vector<ParticleState> states;
      double us = std::numeric_limits<double>::infinity();
      for (int r = 0; r < 3; ++r) {  // best of three
        states.assign(static_cast<size_t>(std::max(1, o.particles)), p.start);
        const auto t0 = std::chrono::steady_clock::now();
        for (ParticleState& s : states)
          for (int i = 0; i < n; ++i) s = step_coupled(kind, s, p, step);
        us = std::min(us, std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() /
                              static_cast<double>(states.size()));
      }
      const double error = glm::length(states[0].x - exact.x);
      const bool blew_up = !std::isfinite(error) || error > travel;
      if (blew_up && std::isnan(first_blowup)) first_blowup = step;
      ChartTable::Row row;
      row.label = name + " dt=1/" + std::to_string(static_cast<int>(std::lround(1.0 / step)));
      if (step > 0.1) row.label = name + " dt=" + std::to_string(step).substr(0, 5);
      row.group = name;
      row.time = us;
      row.error = error;
      row.extra = {step, double(n), p.drag * step, blew_up ? 1.0 : 0.0};
      row.usable = !blew_up;
      t.rows.push_back(row);
    }
    blowup[name] = std::isnan(first_blowup) ? nlohmann::json(nullptr) : nlohmann::json(first_blowup);
  }
  t.summary["first_dt_blowing_up"] = blowup;
  t.summary["distance_travelled"] = travel;
  mark_pareto_front(t);
  return t;
}

}  // namespace pyro
