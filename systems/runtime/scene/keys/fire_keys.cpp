// "fires[]": flipbook fires (Rose 2007, chapter 4).
#include "components/flipbook_fire.h"
#include "systems/runtime/scene/keys/value_shapes.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

const ParameterTable& fire_preparation_keys() {
  static const FlipbookPreparation d{};
  static const ParameterTable table{
      "fires[].preparation", "How the flipbook's frames are cut and softened.",
      {custom_key("crop", kUnit, "[x0, y0, x1, y1] as fractions of the frame, x0 < x1, y0 < y1.",
                  vec4_schema),
       number_key("base_line", Range{0.0, 1.0, false, true}, "Height of the flame's base in the frame.")
           .with_default(d.base_line),
       number_key("soften", Range{0.0, 1.0}, "Fade above the base line; base_line + soften <= 1.")
           .with_default(d.soften)}};
  return table;
}

const ParameterTable& fire_group_keys() {
  static const FlipbookGroup d{};
  static const ParameterTable table{
      "fires[].groups[]", "A group of billboards in rows and columns.",
      {custom_key("offset", kAnyRange, "[lateral, depth] of the group.", vec2_schema),
       integer_key("rows", 1, 1000, "Rows of billboards (in depth).").with_default(d.rows),
       integer_key("columns", 1, 1000, "Billboards per row.").with_default(d.columns),
       number_key("overlap", Range{0.0, 1.0, false, true}, "Fraction of a width shared by neighbours.")
           .with_default(d.overlap),
       number_key("row_spacing", kNonNegative, "World units between rows.").with_default(d.row_spacing),
       custom_key("column_depths", kAnyRange, "Depth offset per column, repeated.", number_list_schema),
       custom_key("start_frames", Range{-1e6, 1e6}, "Start frame per column, repeated.", integer_list_schema),
       custom_key("row_start_step", Range{-1e6, 1e6}, "Start frame added per row.", signed_integer_schema)
           .with_default(d.row_start_step),
       custom_key("increments", Range{-1e6, 1e6}, "Frame increment per column, repeated.",
                  integer_list_schema)}};
  return table;
}

const ParameterTable& fire_keys() {
  static const FlipbookFire d{};
  static const ParameterTable table{
      "fires[]", "A flipbook fire: textured billboards in overlapped groups.",
      {string_key("name", "Label for reports.").with_default(d.name),
       vec3_key("position", kAnyRange, "Centre of the fire's base.").with_default(d.position),
       vec3_key("up", kAnyRange, "The fire's vertical axis; non-zero.").with_default(d.up),
       number_key("width", kPositive, "Billboard width, world units.").with_default(d.width),
       number_key("aspect", kPositive, "Height / width.").with_default(d.aspect),
       number_key("intensity", kNonNegative, "Colour scale of every billboard.").with_default(d.intensity),
       number_key("overlap_exponent", Range{0.0, 4.0}, "Colour scaled by overlap count^-exponent.")
           .with_default(d.overlap_exponent),
       enum_key<FlipbookBlend>("blend", "How a billboard is blended over what is behind it.")
           .with_default(d.blend),
       number_key("frames_per_second", kPositive, "Flipbook steps per second of scene time.")
           .with_default(d.frames_per_second),
       number_key("flicker", Range{0.0, 1.0}, "The flame's and its light's puffing, rms as a fraction of their mean; 0: steady.")
           .with_default(d.flicker),
       number_key("flicker_frequency", kNonNegative, "Puffing frequency in Hz; 0: 1.5 / sqrt(width in metres).")
           .with_default(d.flicker_frequency),
       string_key("flipbook", "A folder of PNG flame frames, a flipbook atlas or a six-way bake (absent: the engine's baked flipbook)."),
       object_key("preparation", fire_preparation_keys(), "How the frames are prepared."),
       objects_key("groups", fire_group_keys(), "Groups of billboards (absent: three overlapped pairs).")
           .with_min_items(1)}};
  return table;
}

}  // namespace pyro
