// "emitters[]": explosion particle emitters and how their particles move.
#include <cstdint>
#include <limits>

#include "components/emitter.h"
#include "components/particle_dynamics.h"
#include "components/render_modes.h"
#include "systems/runtime/scene/keys/value_shapes.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

const ParameterTable& emitter_shape_keys() {
  static const Emitter d{};
  static const ParameterTable table{
      "emitters[].shape", "Where particles are born.",
      {enum_key<EmitterShape>("type", "The shape.").with_default(d.shape),
       vec3_key("position", kAnyRange, "Its centre.").with_default(d.position),
       number_key("radius", kNonNegative, "Sphere or disc radius.").with_default(d.radius),
       boolean_key("surface", "Born on the surface rather than inside.").with_default(d.surface),
       vec3_key("half_extent", kNonNegative, "Box half sizes.").with_default(d.half_extent),
       vec3_key("axis", kAnyRange, "Disc axis; non-zero.").with_default(d.axis)}};
  return table;
}

const ParameterTable& emitter_burst_keys() {
  static const EmitterBurst d{};
  static const ParameterTable table{
      "emitters[].bursts[]", "Particles born at once.",
      {number_key("time", kNonNegative, "Seconds of scene time.").with_default(d.time),
       integer_key("count", 0, 10'000'000, "Number of particles.").as_required()}};
  return table;
}

const ParameterTable& emitter_pattern_keys() {
  static const EmitterPattern d{};
  static const ParameterTable table{
      "emitters[].pattern", "Where births gather: a space-time noise over the shape (flames' tongues).",
      {number_key("frequency", kNonNegative, "Noise cells per world unit; 0: births everywhere.").with_default(d.frequency),
       number_key("speed", kNonNegative, "Noise cells the pattern moves per second.").with_default(d.speed),
       number_key("threshold", Range{-1.0, 1.0}, "Births only where the noise in [-1, 1] reaches this.")
           .with_default(d.threshold)}};
  return table;
}

const ParameterTable& dynamics_curve_keys() {
  static const ParameterTable table{
      "emitters[].dynamics.curves", "Curves over the particle's life, [[t, value], ...], t in [0, 1].",
      {custom_key("size", kNonNegative, "Multiplies the birth radius.", curve_schema),
       custom_key("opacity", kUnit, "Multiplies the density.", curve_schema),
       custom_key("temperature", kNonNegative, "Kelvin over life.", curve_schema),
       custom_key("color", kNonNegative, "Linear RGB over life.", color_curve_schema)}};
  return table;
}

const ParameterTable& dynamics_keys() {
  static const ParticleDynamics d{};
  static const ParameterTable table{
      "emitters[].dynamics", "How the particles move, cool and collide.",
      // gravity_scale, buoyancy and drag: defaults by medium (systems/runtime/scene/emitter_defaults.h).
      {number_key("gravity_scale", kAnyRange, "Times the environment's gravity; default by medium."),
       number_key("buoyancy", kAnyRange, "Boussinesq buoyancy per kelvin above ambient; default by medium."),
       number_key("drag", kNonNegative, "1/s towards the wind; default by medium."),
       number_key("turbulence", kNonNegative, "Turbulent wind speed.").with_default(d.turbulence),
       number_key("turbulence_frequency", kPositive, "1 / world unit.").with_default(d.turbulence_frequency),
       number_key("turbulence_speed", kAnyRange, "How fast the noise pattern moves.")
           .with_default(d.turbulence_speed),
       integer_key("turbulence_seed", 0, std::numeric_limits<std::uint64_t>::max(), "The noise's seed.")
           .with_default(d.turbulence_seed),
       number_key("cooling", kNonNegative, "Newton cooling rate, 1/s.").with_default(d.cooling),
       number_key("smoke_below", kNonNegative, "Fire cooler than this (K) becomes smoke.")
           .with_default(d.smoke_below),
       boolean_key("collide", "Collide with the environment's colliders.").with_default(d.collide),
       number_key("restitution", kUnit, "Bounce.").with_default(d.restitution),
       number_key("friction", kUnit, "Tangential loss at a bounce.").with_default(d.friction),
       object_key("curves", dynamics_curve_keys(), "Curves over life.")}};
  return table;
}

const ParameterTable& emitter_keys() {
  static const Emitter d{};
  static const ParameterTable table{
      "emitters[]", "An explosion emitter: what it spawns and how its particles move.",
      {string_key("name", "Label for reports.").with_default(d.name),
       enum_key<ParticleMedium>("medium", "What the particles are.").with_default(d.medium),
       object_key("shape", emitter_shape_keys(), "Where particles are born."),
       object_key("pattern", emitter_pattern_keys(), "Where births gather over the shape."),
       number_key("rate", kNonNegative, "Particles per second.").with_default(d.rate),
       number_key("start", kNonNegative, "Seconds before the rate starts.").with_default(d.start),
       number_key("duration", kNonNegative, "Seconds the rate lasts (absent: forever)."),
       objects_key("bursts", emitter_burst_keys(), "Particles born at once."),
       vec3_key("direction", kAnyRange, "Launch direction; non-zero.").with_default(d.direction),
       number_key("cone_deg", Range{0.0, 180.0}, "Half-angle of the launch cone.").with_default(d.cone_deg),
       boolean_key("radial", "Launch away from the shape's centre.").with_default(d.radial),
       custom_key("speed", kNonNegative, "Launch speed: a number or a distribution.", distribution_schema),
       custom_key("size", kPositive, "Particle radius: a number or a distribution.", distribution_schema),
       custom_key("lifetime", kPositive, "Seconds: a number or a distribution.", distribution_schema),
       custom_key("density", kNonNegative, "Extinction: a number or a distribution.", distribution_schema),
       custom_key("temperature", kNonNegative, "Kelvin at birth: a number or a distribution; default by medium.", distribution_schema),
       vec3_key("color", kNonNegative, "Linear albedo or colour.").with_default(d.color),
       integer_key("budget", 1, 10'000'000, "Most live particles.").with_default(d.budget),
       integer_key("seed", 0, std::numeric_limits<std::uint64_t>::max(), "Mixed with the scene seed.")
           .with_default(d.seed),
       object_key("dynamics", dynamics_keys(), "How the particles move."),
       enum_key<ParticleShape>("particles", "This emitter's kind; absent: render.particles.")}};
  return table;
}

}  // namespace pyro
