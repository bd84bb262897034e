#include "engine/io/parameter_schema.h"

#include <cmath>
#include <cstdint>
#include <string>

namespace pyro {

using json = nlohmann::json;

json schema_number(double v) {
  if (v == std::floor(v) && std::fabs(v) < 9007199254740992.0) return static_cast<std::int64_t>(v);
  return v;
}

json number_schema(const Range& range) {
  json s = {{"type", "number"}};
  s[range.lo_open ? "exclusiveMinimum" : "minimum"] = schema_number(range.lo);
  s[range.hi_open ? "exclusiveMaximum" : "maximum"] = schema_number(range.hi);
  return s;
}

namespace {

json vec3_schema(const Range& range) {
  return {{"type", "array"}, {"items", number_schema(range)}, {"minItems", 3}, {"maxItems", 3}};
}

// The value's shape, without description or default.
json value_schema(const ParameterKey& key) {
  switch (key.type) {
    case ParameterType::number:
      return number_schema(key.range);
    case ParameterType::integer:
      return {{"type", "integer"}, {"minimum", key.integer_min}, {"maximum", key.integer_max}};
    case ParameterType::boolean:
      return {{"type", "boolean"}};
    case ParameterType::string:
      return {{"type", "string"}};
    case ParameterType::vec3:
      return vec3_schema(key.range);
    case ParameterType::unit_color:
      return {{"anyOf", json::array({number_schema(kUnit), vec3_schema(kUnit)})}};
    case ParameterType::choice: {
      json names = json::array();
      for (std::string_view n : key.choices) names.push_back(std::string(n));
      return {{"type", "string"}, {"enum", names}};
    }
    case ParameterType::object:
      return object_schema(*key.table);
    case ParameterType::objects:
    {
      json s = {{"type", "array"}, {"items", object_schema(*key.table)}};
      if (key.min_items > 0) s["minItems"] = key.min_items;
      return s;
    }
    case ParameterType::custom:
      return key.custom_schema(key);
  }
  return json::object();
}

// A key that applies only with some values of a choice key: absent unless the choice holds one
// (and present when it does, for a required key).
json applicability_schema(const ParameterKey& key) {
  json values = json::array();
  for (std::string_view v : key.only_with_values) values.push_back(std::string(v));
  const std::string choice(key.only_with_key);
  const json name = json::array({std::string(key.name)});
  json s = {{"if", {{"properties", {{choice, {{"enum", values}}}}}, {"required", json::array({choice})}}},
            {"else", {{"not", {{"required", name}}}}}};
  if (key.required) s["then"] = {{"required", name}};
  return s;
}

}  // namespace

json key_schema(const ParameterKey& key) {
  json s = value_schema(key);
  if (!key.description.empty()) s["description"] = std::string(key.description);
  if (!key.default_value.is_null()) s["default"] = key.default_value;
  return s;
}

json object_schema(const ParameterTable& table) {
  json s = {{"type", "object"}};
  if (!table.description.empty()) s["description"] = std::string(table.description);
  json properties = json::object();
  json required = json::array();
  for (const ParameterKey& key : table.keys) {
    properties[std::string(key.name)] = key_schema(key);
    if (key.required && key.only_with_key.empty()) required.push_back(std::string(key.name));
  }
  s["properties"] = properties;
  if (!required.empty()) s["required"] = required;
  json conditions = json::array();
  for (const ParameterKey& key : table.keys)
    if (!key.only_with_key.empty()) conditions.push_back(applicability_schema(key));
  if (!conditions.empty()) s["allOf"] = conditions;
  s["additionalProperties"] = false;
  return s;
}

}  // namespace pyro
