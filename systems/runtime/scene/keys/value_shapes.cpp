#include "systems/runtime/scene/keys/value_shapes.h"

#include "engine/io/parameter_schema.h"

namespace pyro {

using json = nlohmann::json;

namespace {

json array_of(json items, std::size_t lo, std::size_t hi) {
  return {{"type", "array"}, {"items", std::move(items)}, {"minItems", lo}, {"maxItems", hi}};
}

json integer_schema(const Range& range) {
  json s = number_schema(range);
  s["type"] = "integer";
  return s;
}

// [t, value] pairs.
json keys_schema(json value) {
  json pair = {{"type", "array"},
               {"prefixItems", json::array({number_schema(kUnit), std::move(value)})},
               {"minItems", 2},
               {"maxItems", 2}};
  return {{"type", "array"}, {"items", pair}, {"minItems", 1}};
}

}  // namespace

json distribution_schema(const ParameterKey& key) {
  const json n = number_schema(key.range);
  const json uniform = {{"type", "object"},
                        {"properties", {{"min", n}, {"max", n}}},
                        {"required", {"min", "max"}},
                        {"additionalProperties", false}};
  const json normal = {{"type", "object"},
                       {"properties", {{"mean", n}, {"stddev", number_schema(kNonNegative)}, {"min", n}, {"max", n}}},
                       {"required", {"mean", "stddev"}},
                       {"additionalProperties", false}};
  return {{"anyOf", json::array({n, uniform, normal})}};
}

json curve_schema(const ParameterKey& key) { return keys_schema(number_schema(key.range)); }

json color_curve_schema(const ParameterKey& key) {
  return keys_schema(array_of(number_schema(key.range), 3, 3));
}

json temperature_table_schema(const ParameterKey& key) {
  const json pair = {{"type", "array"},
                     {"prefixItems", json::array({number_schema(kAnyRange), number_schema(key.range)})},
                     {"minItems", 2},
                     {"maxItems", 2}};
  return {{"type", "array"}, {"items", pair}, {"minItems", 2}, {"maxItems", 1024}};
}

json volume_path_schema(const ParameterKey&) {
  return {{"type", "string"},
          {"pattern", "\\.([vV][dD][bB]|[pP][yY][rR][oO][pP]|[pP][yY][rR][oO][sS][eE][qQ]/?)$"}};
}

json vec2_schema(const ParameterKey& key) { return array_of(number_schema(key.range), 2, 2); }

json vec4_schema(const ParameterKey& key) { return array_of(number_schema(key.range), 4, 4); }

json number_list_schema(const ParameterKey& key) { return array_of(number_schema(key.range), 1, 1000); }

json integer_list_schema(const ParameterKey& key) { return array_of(integer_schema(key.range), 1, 1000); }

json signed_integer_schema(const ParameterKey& key) { return integer_schema(key.range); }

}  // namespace pyro
