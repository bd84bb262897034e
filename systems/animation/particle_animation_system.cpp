#include "systems/animation/particle_animation_system.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <utility>
#include <vector>

#include "components/emitter.h"
#include "components/frame_clock.h"
#include "components/particle_dynamics.h"
#include "components/particle_medium.h"
#include "components/particle_set.h"
#include "components/simulation_environment.h"
#include "engine/ecs/world.h"
#include "systems/animation/curl_noise.h"
#include "systems/animation/life_curve_eval.h"
#include "systems/animation/particle_integrator.h"

namespace pyro {

namespace {

// Reflects the velocity's component into the surface (outward normal n): normal part reversed
// and scaled by restitution, tangential part scaled by (1 − friction).
void respond(glm::vec3& v, const glm::vec3& n, float restitution, float friction) {
  const float vn = glm::dot(v, n);
  if (vn >= 0.0f) return;
  const glm::vec3 vt = v - vn * n;
  v = vt * (1.0f - friction) - restitution * vn * n;
}

}  // namespace

bool collide_particle(glm::vec3& x, glm::vec3& v, const SimulationEnvironment& env, float restitution,
                      float friction) {
  bool hit = false;
  if (env.ground && x.y < env.ground_height) {
    x.y = env.ground_height;
    respond(v, {0.0f, 1.0f, 0.0f}, restitution, friction);
    hit = true;
  }
  for (const SphereCollider& s : env.spheres) {
    const glm::vec3 d = x - s.center;
    const float len = glm::length(d);
    if (len >= s.radius) continue;
    const glm::vec3 n = len > 1e-6f ? d / len : glm::vec3(0.0f, 1.0f, 0.0f);
    x = s.center + n * s.radius;
    respond(v, n, restitution, friction);
    hit = true;
  }
  for (const BoxCollider& b : env.boxes) {
    if (x.x <= b.min.x || x.x >= b.max.x || x.y <= b.min.y || x.y >= b.max.y || x.z <= b.min.z ||
        x.z >= b.max.z)
      continue;
    // Out through the nearest face.
    float best = x.x - b.min.x;
    glm::vec3 n(-1.0f, 0.0f, 0.0f);
    const float cand[5] = {b.max.x - x.x, x.y - b.min.y, b.max.y - x.y, x.z - b.min.z, b.max.z - x.z};
    const glm::vec3 normals[5] = {{1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    for (int i = 0; i < 5; ++i)
      if (cand[i] < best) best = cand[i], n = normals[i];
    x += n * best;
    respond(v, n, restitution, friction);
    hit = true;
  }
  return hit;
}

namespace {

// Per-step constants of one set's update (the exponential integrator's factors, the forcing).
struct StepFactors {
  float ta, k, e_drag, phi1, phi2, e_cool;
  glm::vec3 gravity, noise_shift;
  bool turbulent, t_curve, s_curve, o_curve, c_curve;
};

StepFactors step_factors(const ParticleDynamics& d, const SimulationEnvironment& env, float dt,
                         double time) {
  StepFactors f;
  f.ta = env.ambient_temperature;
  f.k = d.drag;
  f.e_drag = std::exp(-f.k * dt);
  f.phi1 = exp_phi1(f.k, dt), f.phi2 = exp_phi2(f.k, dt);
  f.e_cool = std::exp(-d.cooling * dt);
  f.gravity = env.gravity * d.gravity_scale;
  f.turbulent = d.turbulence != 0.0f;
  f.noise_shift = glm::vec3(0.0f, 1.0f, 0.5f) * static_cast<float>(time * d.turbulence_speed);
  f.t_curve = !d.temperature.keys.empty(), f.s_curve = !d.size.keys.empty(),
  f.o_curve = !d.opacity.keys.empty(), f.c_curve = !d.color.keys.empty();
  return f;
}

// Particles [begin, end) of `p` one step on: each particle's update reads and writes only its
// own slots, so any split of the range gives the same bits.
void advance_particles(ParticlePool& p, const ParticleDynamics& d, const SimulationEnvironment& env,
                       const StepFactors& f, float dt, std::size_t begin, std::size_t end) {
  for (std::size_t i = begin; i < end; ++i) {
    float temp = p.temperature[i];
    // Cooling (exact exponential decay toward ambient) or the temperature curve.
    temp = f.t_curve ? evaluate_curve(d.temperature, p.age[i] / p.lifetime[i]).x
                     : f.ta + (temp - f.ta) * f.e_cool;
    if (p.medium[i] == static_cast<uint8_t>(ParticleMedium::fire) && temp < d.smoke_below)
      p.medium[i] = static_cast<uint8_t>(ParticleMedium::smoke);
    p.temperature[i] = temp;

    glm::vec3 x(p.px[i], p.py[i], p.pz[i]), v(p.vx[i], p.vy[i], p.vz[i]);
    const glm::vec3 a = f.gravity + glm::vec3(0.0f, d.buoyancy * (temp - f.ta), 0.0f);
    glm::vec3 w = env.wind;
    if (f.turbulent)
      w += d.turbulence * curl_noise(x * d.turbulence_frequency + f.noise_shift, d.turbulence_seed);
    const glm::vec3 forcing = a + f.k * w;
    // A particle born within the last step (systems/emitter: as old as the time since its birth)
    // catches up over that time too: it is stepped over its age plus the step.
    float phi1 = f.phi1, phi2 = f.phi2, e_drag = f.e_drag;
    if (p.age[i] > 0.0f && p.age[i] < dt) {
      const float h = dt + p.age[i];
      phi1 = exp_phi1(f.k, h), phi2 = exp_phi2(f.k, h), e_drag = std::exp(-f.k * h);
    }
    x += v * phi1 + forcing * phi2;
    v = v * e_drag + forcing * phi1;
    if (d.collide) collide_particle(x, v, env, d.restitution, d.friction);
    p.px[i] = x.x, p.py[i] = x.y, p.pz[i] = x.z;
    p.vx[i] = v.x, p.vy[i] = v.y, p.vz[i] = v.z;

    p.age[i] += dt;
    const float life = std::min(p.age[i] / p.lifetime[i], 1.0f);
    if (f.s_curve) p.radius[i] = p.size0[i] * evaluate_curve(d.size, life).x;
    if (f.o_curve) p.opacity[i] = std::clamp(evaluate_curve(d.opacity, life).x, 0.0f, 1.0f);
    if (f.c_curve) {
      const glm::vec3 c = evaluate_curve(d.color, life);
      p.r[i] = c.x, p.g[i] = c.y, p.b[i] = c.z;
    }
  }
}

// Particles per task when a set's update is split across threads: a step costs roughly a
// curl-noise evaluation per particle, so smaller sets run in one piece.
constexpr std::size_t kAnimatedParticlesPerTask = 512;

}  // namespace

std::size_t animate_particles(ParticlePool& p, const ParticleDynamics& d,
                              const SimulationEnvironment& env, float dt, double time) {
  const StepFactors f = step_factors(d, env, dt, time);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, p.size(), kAnimatedParticlesPerTask),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      advance_particles(p, d, env, f, dt, r.begin(), r.end());
                    });
  // Removal keeps the survivors' order: sequential.
  return p.kill_if([&](std::size_t i) { return p.age[i] >= p.lifetime[i]; });
}

ecs::SystemDesc animation_system() {
  return {.name = "animation",
          .phase = ecs::Phase::simulate,
          .access = ecs::Access::of<ecs::Reads<FrameClock, SimulationEnvironment, ParticleDynamics>,
                                    ecs::Writes<ParticleSet>>(),
          .run =
              [](ecs::World& world) {
                const FrameClock& clock = world.resource<const FrameClock>();
                const SimulationEnvironment& env = world.resource<const SimulationEnvironment>();
                // Step 0 shows the emitted state; after a prewarm of P steps frame 0 is step P.
                if (clock.frame + env.prewarm_steps == 0) return;
                const double t = static_cast<double>(clock.frame + env.prewarm_steps) * clock.dt;
                // Every set on its own (and large sets split further): the sets share nothing.
                std::vector<std::pair<const ParticleDynamics*, ParticlePool*>> sets;
                world.each<const ParticleDynamics, ParticleSet>(
                    [&](const ParticleDynamics& d, ParticleSet& s) {
                      sets.emplace_back(&d, &s.pool);
                    });
                tbb::parallel_for(std::size_t(0), sets.size(), [&](std::size_t k) {
                  animate_particles(*sets[k].second, *sets[k].first, env, clock.dt, t);
                });
              },
          // Both move ParticleSets (of different entities; access is per type).
          .after = {"cloud_drift"}};
}

}  // namespace pyro
