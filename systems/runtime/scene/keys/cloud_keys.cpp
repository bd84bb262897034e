// "clouds[]": identical Gaussian particles placed at random in a box.
#include <cstdint>
#include <limits>

#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

const ParameterTable& cloud_box_keys() {
  static const CloudDescription d{};
  static const ParameterTable table{
      "clouds[].box", "Where the particles are placed; min < max on every axis.",
      {vec3_key("min", kAnyRange, "Lower corner.").with_default(d.box_min),
       vec3_key("max", kAnyRange, "Upper corner.").with_default(d.box_max)}};
  return table;
}

const ParameterTable& cloud_keys() {
  static const CloudDescription d{};
  static const ParameterTable table{
      "clouds[]", "A cloud of identical Gaussian particles placed uniformly at random in a box.",
      {string_key("name", "Label for reports.").with_default(d.name),
       integer_key("count", 1, 10'000'000, "Number of particles.").as_required(),
       number_key("radius", kPositive, "Particle radius, world units.").with_default(d.radius),
       number_key("density", kUnit, "Opacity at the kernel centre.").with_default(d.density),
       unit_color_key("color", "Linear colour: a grey level or [r, g, b].").with_default(d.color),
       object_key("box", cloud_box_keys(), "Where the particles are placed."),
       integer_key("seed", 0, std::numeric_limits<std::uint64_t>::max(), "Mixed with the scene seed.")
           .with_default(d.seed),
       vec3_key("drift", kAnyRange, "Common drift velocity, world units per second.").with_default(d.drift),
       number_key("jitter", kNonNegative, "Per-particle random speed, world units per second.")
           .with_default(d.jitter),
       enum_key<ParticleShape>("particles", "This cloud's kind; absent: render.particles.")}};
  return table;
}

}  // namespace pyro
