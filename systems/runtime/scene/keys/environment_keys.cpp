// "environment": what every emitter shares (gravity, wind, colliders, budget, prewarm).
#include "components/simulation_environment.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

const ParameterTable& ground_keys() {
  static const SimulationEnvironment d{};
  static const ParameterTable table{
      "environment.ground", "A ground plane the particles collide with.",
      {number_key("height", kAnyRange, "Its height y.").with_default(d.ground_height)}};
  return table;
}

const ParameterTable& sphere_collider_keys() {
  static const SphereCollider d{};
  static const ParameterTable table{
      "environment.spheres[]", "A sphere the particles collide with.",
      {vec3_key("center", kAnyRange, "Its centre.").with_default(d.center),
       number_key("radius", kPositive, "Its radius.").with_default(d.radius)}};
  return table;
}

const ParameterTable& box_collider_keys() {
  static const BoxCollider d{};
  static const ParameterTable table{
      "environment.boxes[]", "An axis-aligned box the particles collide with; min < max on every axis.",
      {vec3_key("min", kAnyRange, "Lower corner.").with_default(d.min),
       vec3_key("max", kAnyRange, "Upper corner.").with_default(d.max)}};
  return table;
}

const ParameterTable& environment_keys() {
  static const SimulationEnvironment d{};
  static const SceneDescription scene{};
  static const ParameterTable table{
      "environment", "What all emitters share.",
      {vec3_key("gravity", kAnyRange, "Acceleration, world units / s^2.").with_default(d.gravity),
       vec3_key("wind", kAnyRange, "Air velocity, world units / s.").with_default(d.wind),
       number_key("ambient_temperature", kPositive, "K.").with_default(d.ambient_temperature),
       object_key("ground", ground_keys(), "A ground plane (present: on)."),
       objects_key("spheres", sphere_collider_keys(), "Sphere colliders."),
       objects_key("boxes", box_collider_keys(), "Box colliders."),
       integer_key("particle_budget", 1, 100'000'000, "Live particles over all emitters.")
           .with_default(d.particle_budget),
       number_key("prewarm", Range{0.0, 3600.0}, "Seconds simulated before frame 0.")
           .with_default(scene.prewarm)}};
  return table;
}

}  // namespace pyro
