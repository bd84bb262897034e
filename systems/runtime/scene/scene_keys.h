#pragma once
// The scene file's keys, one table per concept (systems/runtime/scene/keys/, one file each): names,
// types, ranges, defaults (read from the description structs' default member initialisers),
// descriptions, enumeration names and required keys. The loader reads through these tables, and
// `pyro schema` and the documentation checks are derived from them (docs/scene_format.md).
#include <nlohmann/json.hpp>

#include "engine/io/parameter_table.h"

namespace pyro {

const ParameterTable& scene_keys();  // the top level; the others hang below it
const ParameterTable& output_keys();
const ParameterTable& footprint_keys();
const ParameterTable& budget_keys();
const ParameterTable& quality_keys();
const ParameterTable& camera_keys();
const ParameterTable& stereo_keys();
const ParameterTable& light_keys();          // "light": the short form
const ParameterTable& light_source_keys();   // one entry of "lights"
const ParameterTable& light_keyframe_keys();  // one entry of "lights[].keys"
const ParameterTable& shadow_keys();
const ParameterTable& scattering_keys();
const ParameterTable& render_keys();
const ParameterTable& render_fire_keys();
const ParameterTable& cloud_keys();
const ParameterTable& cloud_box_keys();
const ParameterTable& mesh_keys();
const ParameterTable& volume_keys();
const ParameterTable& volume_emission_keys();
const ParameterTable& volume_temperature_keys();
const ParameterTable& fire_keys();
const ParameterTable& fire_preparation_keys();
const ParameterTable& fire_group_keys();
const ParameterTable& emitter_keys();
const ParameterTable& emitter_shape_keys();
const ParameterTable& emitter_burst_keys();
const ParameterTable& emitter_pattern_keys();
const ParameterTable& dynamics_keys();
const ParameterTable& dynamics_curve_keys();
const ParameterTable& environment_keys();
const ParameterTable& ground_keys();
const ParameterTable& sphere_collider_keys();
const ParameterTable& box_collider_keys();

// The JSON Schema (draft 2020-12) of a scene file, from scene_keys().
nlohmann::json scene_schema();

}  // namespace pyro
