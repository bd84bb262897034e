#pragma once
// JSON Schema (draft 2020-12) of the objects a parameter table describes: types, ranges
// (minimum / exclusiveMinimum / maximum / exclusiveMaximum), defaults, descriptions, enumerations,
// required keys and `additionalProperties: false`, nested tables and arrays of them. Checks that
// involve several keys stay with the reader; a schema states only what one value must be.
#include <nlohmann/json.hpp>

#include "engine/io/parameter_table.h"

namespace pyro {

// The schema of one object holding `table`'s keys.
nlohmann::json object_schema(const ParameterTable& table);

// The schema of one key's value (with its description and default).
nlohmann::json key_schema(const ParameterKey& key);

// A number as JSON: whole values as integers (1000000 rather than 1000000.0).
nlohmann::json schema_number(double v);

// {"type": "number", "minimum" ... } for `range`.
nlohmann::json number_schema(const Range& range);

}  // namespace pyro
