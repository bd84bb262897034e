#include "systems/animation/drift_system.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include <glm/trigonometric.hpp>

#include "components/camera.h"
#include "components/camera_orbit.h"
#include "components/cloud_volume.h"
#include "components/frame_clock.h"
#include "components/particle_set.h"
#include "engine/ecs/world.h"

namespace pyro {

namespace {
// Particles per task when drifting is split across threads.
constexpr size_t kDriftParticlesPerTask = 16384;

inline float wrap(float v, float lo, float extent) {
  // Periodic wrap into [lo, lo + extent).
  float t = (v - lo) / extent;
  t -= std::floor(t);
  return lo + t * extent;
}
}  // namespace

void drift_particles(const CloudVolume& c, ParticleSet& set, float dt) {
  ParticlePool& p = set.pool;
  const glm::vec3 extent = c.box_max - c.box_min;
  // Each particle moves alone, so the chunks may run on any threads with the same result.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, p.size(), kDriftParticlesPerTask),
                    [&](const tbb::blocked_range<size_t>& r) {
    // The arrays are distinct buffers; ivdep lets g++ vectorise (see particle_pool.h).
#pragma GCC ivdep
    for (size_t i = r.begin(); i < r.end(); ++i) {
      p.px[i] = wrap(p.px[i] + p.vx[i] * dt, c.box_min.x, extent.x);
      p.py[i] = wrap(p.py[i] + p.vy[i] * dt, c.box_min.y, extent.y);
      p.pz[i] = wrap(p.pz[i] + p.vz[i] * dt, c.box_min.z, extent.z);
    }
  });
}

ecs::SystemDesc cloud_drift_system() {
  return {
      .name = "cloud_drift",
      .phase = ecs::Phase::simulate,
      .access = ecs::Access::of<ecs::Reads<CloudVolume, FrameClock>, ecs::Writes<ParticleSet>>(),
      .run = [](ecs::World& world) {
        const FrameClock& clock = world.resource<const FrameClock>();
        if (clock.frame == 0) return;  // frame 0 shows the emitted state
        const float dt = clock.dt;
        world.each<const CloudVolume, ParticleSet>([dt](const CloudVolume& c, ParticleSet& s) {
          if (c.drift != glm::vec3(0.0f) || c.jitter > 0.0f) drift_particles(c, s, dt);
        });
      }};
}

ecs::SystemDesc camera_orbit_system() {
  return {.name = "camera_orbit",
          .phase = ecs::Phase::simulate,
          .access = ecs::Access::of<ecs::Reads<CameraOrbit, FrameClock>, ecs::Writes<Camera>>(),
          .run = [](ecs::World& world) {
            const double t = world.resource<const FrameClock>().time();
            world.each<Camera, const CameraOrbit>([t](Camera& cam, const CameraOrbit& orbit) {
              const float a = glm::radians(static_cast<float>(orbit.deg_per_second * t));
              const glm::vec3 d = orbit.start_position - cam.target;
              const float c = std::cos(a), s = std::sin(a);
              cam.position = cam.target + glm::vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
            });
          }};
}

}  // namespace pyro
