// "camera": the viewpoint and its stereo pair.
#include "components/stereo_camera.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

const ParameterTable& stereo_keys() {
  static const CameraDescription d{};
  static const ParameterTable table{
      "camera.stereo", "The stereo pair, used when a stereo output mode is chosen.",
      {number_key("interocular", kNonNegative, "Distance between the eyes, world units.")
           .with_default(d.interocular),
       number_key("zero_parallax_distance", kPositive,
                  "View depth at which both eyes' images coincide (the screen plane).")
           .with_default(d.zero_parallax_distance),
       enum_key<EyeOrder>("eye_order", "\"right-left\" puts the right eye's view first.")
           .with_default(d.swap_eyes ? EyeOrder::right_left : EyeOrder::left_right)}};
  return table;
}

const ParameterTable& camera_keys() {
  static const CameraDescription d{};
  static const ParameterTable table{
      "camera", "The viewpoint.",
      {vec3_key("position", kAnyRange, "Eye position (centre between the eyes), world units.")
           .with_default(d.position),
       vec3_key("target", kAnyRange, "Point looked at; differs from position.").with_default(d.target),
       vec3_key("up", kAnyRange, "Up direction; non-zero, not parallel to the view direction.")
           .with_default(d.up),
       number_key("fov_y_deg", Range{0.0, 180.0, true, true}, "Vertical field of view in degrees.")
           .with_default(d.fov_y_deg),
       number_key("near", kPositive, "Near clipping distance.").with_default(d.near),
       number_key("far", kPositive, "Far clipping distance, greater than near.").with_default(d.far),
       number_key("orbit_deg_per_second", kAnyRange,
                  "Scripted orbit about the target around the vertical axis; 0 keeps it still.")
           .with_default(d.orbit_deg_per_second),
       object_key("stereo", stereo_keys(), "The stereo pair.")}};
  return table;
}

}  // namespace pyro
