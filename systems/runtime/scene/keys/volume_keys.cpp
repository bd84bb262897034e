// "volumes[]": volumes read from files (OpenVDB grids, particle files, particle sequences).
#include <string_view>

#include "systems/runtime/scene/keys/value_shapes.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

const ParameterTable& volume_temperature_keys() {
  static const VolumeEmissionDescription d{};
  static const ParameterTable table{
      "volumes[].emission.temperature",
      "Grid value to kelvin: kelvin = scale value + offset, or a table (not both).",
      {custom_key("table", Range{0.0, 1e6}, "[[value, kelvin], ...], values strictly ascending.",
                  temperature_table_schema),
       number_key("scale", Range{-1e6, 1e6}, "kelvin = scale value + offset.").with_default(d.scale),
       number_key("offset", Range{-1e6, 1e6}, "kelvin = scale value + offset.").with_default(d.offset)}};
  return table;
}

const ParameterTable& volume_emission_keys() {
  static const ParameterTable table{
      "volumes[].emission", "The fire: how temperature values become kelvin and how bright it glows.",
      {object_key("temperature", volume_temperature_keys(),
                  "Absent: the particle file's recorded map, else the automatic one."),
       number_key("intensity", Range{0.0, 1e6},
                  "The largest component of the hottest radiance (absent: the volume's exposure).")}};
  return table;
}

const ParameterTable& volume_keys() {
  static const VolumeDescription d{};
  static const ParameterTable table{
      "volumes[]", "A volume read from a file when the scene is loaded.",
      {string_key("name", "Label for reports.").with_default(d.name),
       custom_key("file", kAnyRange,
                  "The .vdb or .pyrop file or .pyroseq folder, relative to the scene file's folder.",
                  volume_path_schema)
           .as_required(),
       custom_key("fallback", kAnyRange, "Used when file does not exist.", volume_path_schema),
       integer_key("start_frame", 0, 1'000'000'000, "Sequences only: the source frame at time 0."),
       boolean_key("loop", "Sequences only: play again after the last frame.").with_default(d.sequence.loop),
       number_key("speed", Range{0.0, 1000.0, true, false}, "Sequences only: times the sequence's fps.")
           .with_default(d.sequence.speed),
       string_key("grid", "VDB only: the grid to import (default \"density\", else the first float grid)."),
       string_key("temperature_grid", "VDB only: the grid the fire comes from; \"none\": no fire."),
       object_key("emission", volume_emission_keys(), "The volume's fire."),
       integer_key("grid_index", 0, 1'000'000, "VDB only: the grid at this position; not with grid."),
       number_key("error", Range{0.0, 1.0, true, false}, "VDB only: the image error target.")
           .with_default(d.error),
       number_key("extinction", kPositive, "VDB only: extinction per unit density (absent: automatic)."),
       choice_key("anchor", {"center", "origin"}, "The point of the file placed at position.")
           .with_default(std::string_view(d.anchor_center ? "center" : "origin")),
       vec3_key("position", kAnyRange, "Where the anchor goes.").with_default(d.position),
       number_key("scale", kPositive, "Uniform scale about the anchor.").with_default(d.scale),
       number_key("size", kPositive, "Instead of scale: the bounding box's longest side.")}};
  return table;
}

}  // namespace pyro
