#pragma once
// A particle emitter for explosions (dust, smoke, fire): where particles are born, how many per
// second and in bursts, and the distributions of their initial state. The emitter system
// (systems/emitter/emitter_system.h) spawns into the entity's ParticleSet; the entity's
// ParticleDynamics says how they then move.
#include "engine/core/enum_names.h"
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "components/distribution.h"
#include "components/particle_medium.h"
#include "engine/core/rng.h"

namespace pyro {

enum class EmitterShape { point, sphere, box, disc };
inline constexpr EnumName<EmitterShape> emitter_shape_names[] = {{EmitterShape::point, "point"},
                                                              {EmitterShape::sphere, "sphere"},
                                                              {EmitterShape::box, "box"},
                                                              {EmitterShape::disc, "disc"}};
constexpr const auto& enum_names(EmitterShape) { return emitter_shape_names; }

struct EmitterBurst {
  float time = 0.0f;   // seconds of scene time (prewarm included: t = 0 is the scene's start)
  uint32_t count = 0;
};

// Where births gather: a particle is born only where a space-time value noise over the emitter's
// shape, n(frequency p + speed t d) with d a fixed diagonal, reaches `threshold` (its birth point
// is drawn again, up to kPatternTries times, else the highest seen is kept). Flames' tongues: hot
// patches that rise as streaks and break off when their patch moves on. frequency 0: everywhere.
struct EmitterPattern {
  float frequency = 0.0f;   // noise cells per world unit
  float speed = 0.0f;       // noise cells per second
  float threshold = -1.0f;  // in [−1, 1]

  bool operator==(const EmitterPattern&) const = default;
};
inline constexpr int kPatternTries = 16;

struct Emitter {
  std::string name;                        // for reports
  ParticleMedium medium = ParticleMedium::smoke;
  // Shape, centred on `position`: a point; a sphere of `radius` (volume, or its surface when
  // `surface`); a box of half sides `half_extent`; a disc of `radius` facing `axis`.
  EmitterShape shape = EmitterShape::point;
  glm::vec3 position{0.0f};
  float radius = 1.0f;
  bool surface = false;
  glm::vec3 half_extent{1.0f};
  glm::vec3 axis{0.0f, 1.0f, 0.0f};
  EmitterPattern pattern;
  // Timing: `rate` particles per second from `start` for `duration` seconds (fractions carry
  // over: after time t, floor(rate · (t − start)) have been emitted), plus bursts.
  float rate = 0.0f;
  float start = 0.0f;
  float duration = std::numeric_limits<float>::infinity();
  std::vector<EmitterBurst> bursts;
  // Initial velocity: speed × a direction uniform in the cone of half-angle `cone_deg` about
  // `direction`, or, when `radial`, pointing away from `position` (a point emitter: uniform).
  glm::vec3 direction{0.0f, 1.0f, 0.0f};
  float cone_deg = 0.0f;
  bool radial = false;
  Distribution speed = Distribution::constant(0.0f);
  Distribution size = Distribution::constant(0.5f);       // particle radius, world units
  Distribution lifetime = Distribution::constant(5.0f);   // seconds
  Distribution density = Distribution::constant(0.4f);    // τ (paper section 2)
  Distribution temperature = Distribution::constant(0.0f);  // kelvin
  glm::vec3 color{1.0f};                   // linear RGB (dust / smoke albedo colour)
  uint32_t budget = 1000;                  // most live particles; the pool's capacity
  uint64_t seed = 1;                       // already mixed with the scene seed

  // State, advanced by the emitter system.
  double time = 0.0;                       // scene time emitted up to
  uint64_t rate_emitted = 0;               // particles the rate has asked for so far
  std::size_t next_burst = 0;              // bursts are sorted by time; the first not yet fired
  uint64_t spawned = 0;                    // particles actually spawned
  uint64_t over_budget = 0;                // spawns refused by this or the scene budget
  Rng rng{1};                              // seeded from `seed` when the entity is built
};

}  // namespace pyro
