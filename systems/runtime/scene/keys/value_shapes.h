#pragma once
// JSON Schemas of the scene's values that are neither a number, a vector nor an object of keys:
// distributions, curves over life, lists, the temperature table, volume paths. Each is built
// from its key (range, description) so that the range is written once, in the key's table.
#include <cstddef>

#include <nlohmann/json.hpp>

#include "engine/io/parameter_table.h"

namespace pyro {

// A number (constant), {"min", "max"} (uniform) or {"mean", "stddev", "min"?, "max"?} (normal).
nlohmann::json distribution_schema(const ParameterKey& key);
// [[t, value], ...], t in [0, 1]; value a number in the key's range.
nlohmann::json curve_schema(const ParameterKey& key);
// [[t, [r, g, b]], ...].
nlohmann::json color_curve_schema(const ParameterKey& key);
// [[value, kelvin], ...], 2 to 1024 pairs, kelvin in the key's range.
nlohmann::json temperature_table_schema(const ParameterKey& key);
// A path ending in .vdb, .pyrop or .pyroseq (any case).
nlohmann::json volume_path_schema(const ParameterKey& key);
// [a, b]: 2 numbers in the key's range.
nlohmann::json vec2_schema(const ParameterKey& key);
// [x0, y0, x1, y1]: 4 numbers in the key's range.
nlohmann::json vec4_schema(const ParameterKey& key);
// 1 to 1000 numbers in the key's range.
nlohmann::json number_list_schema(const ParameterKey& key);
// 1 to 1000 whole numbers in the key's range.
nlohmann::json integer_list_schema(const ParameterKey& key);
// One whole number in the key's range.
nlohmann::json signed_integer_schema(const ParameterKey& key);

}  // namespace pyro
