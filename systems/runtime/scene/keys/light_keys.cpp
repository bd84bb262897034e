// "light" (one directional and one ambient light) and "lights" (any number of each, with keys).
#include "components/ambient_light.h"
#include "components/directional_light.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

const ParameterTable& light_keys() {
  static const DirectionalLight sun{};
  static const AmbientLight sky{};
  static const ParameterTable table{
      "light", "One directional light and the ambient light.",
      {vec3_key("direction", kAnyRange,
                "Direction the light travels (not towards the light); non-zero, normalised.")
           .with_default(sun.direction),
       vec3_key("color", kNonNegative, "Linear RGB radiance of the light.").with_default(sun.color),
       vec3_key("ambient", kNonNegative, "Linear RGB ambient term.").with_default(sky.color)}};
  return table;
}

const ParameterTable& light_keyframe_keys() {
  static const ParameterTable table{
      "lights[].keys[]", "The light at one time; the light's own values are the defaults.",
      {number_key("time", kNonNegative, "Seconds of scene time; keys in increasing order.").as_required(),
       vec3_key("direction", kAnyRange, "Direction the light travels; non-zero."),
       vec3_key("color", kNonNegative, "Linear RGB."),
       number_key("intensity", kNonNegative, "Scales color.")}};
  return table;
}

const ParameterTable& light_source_keys() {
  static const DirectionalLight sun{};
  static const ParameterTable table{
      "lights[]", "A directional light (direction, color, intensity, keys) or an ambient one (color).",
      {choice_key("type", {"directional", "ambient"}, "A light at infinity, or light from every direction.")
           .as_required(),
       vec3_key("color", kNonNegative, "Linear RGB."),
       vec3_key("direction", kAnyRange, "Directional: the direction the light travels; non-zero.")
           .with_default(sun.direction),
       number_key("intensity", kNonNegative, "Directional: scales color.").with_default(sun.intensity),
       objects_key("keys", light_keyframe_keys(), "Directional: the light over time, times ascending.")}};
  return table;
}

}  // namespace pyro
