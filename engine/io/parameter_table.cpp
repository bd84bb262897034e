#include "engine/io/parameter_table.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "engine/io/parameter_text.h"

namespace pyro {

nlohmann::json float_json(float v) {
  if (!std::isfinite(v)) return nullptr;  // no JSON number: "no default" rather than a wrong one
  return nlohmann::json::parse(format_float(v));
}

ParameterKey ParameterKey::with_default(float v) const {
  ParameterKey k = *this;
  k.default_value = float_json(v);
  return k;
}

ParameterKey ParameterKey::with_default(const glm::vec3& v) const {
  ParameterKey k = *this;
  k.default_value = nlohmann::json::array({float_json(v.x), float_json(v.y), float_json(v.z)});
  return k;
}

ParameterKey ParameterKey::with_integer_default(std::uint64_t v) const {
  ParameterKey k = *this;
  k.default_value = v;
  return k;
}

ParameterKey ParameterKey::with_default(bool v) const {
  ParameterKey k = *this;
  k.default_value = v;
  return k;
}

ParameterKey ParameterKey::with_default(std::string_view v) const {
  ParameterKey k = *this;
  k.default_value = std::string(v);
  return k;
}

ParameterKey ParameterKey::as_required() const {
  ParameterKey k = *this;
  k.required = true;
  return k;
}

ParameterKey ParameterKey::with_min_items(std::size_t n) const {
  ParameterKey k = *this;
  k.min_items = n;
  return k;
}

ParameterKey ParameterKey::only_for(std::string_view choice_key, std::vector<std::string_view> values) const {
  ParameterKey k = *this;
  k.only_with_key = choice_key;
  k.only_with_values = std::move(values);
  return k;
}

const ParameterKey* ParameterTable::find(std::string_view key_name) const {
  for (const ParameterKey& k : keys)
    if (k.name == key_name) return &k;
  return nullptr;
}

const ParameterKey& ParameterTable::key(std::string_view key_name) const {
  if (const ParameterKey* k = find(key_name)) return *k;
  throw std::logic_error("the key table \"" + std::string(name) + "\" declares no key \"" +
                         std::string(key_name) + "\"");
}

namespace {

ParameterKey make_key(std::string_view name, ParameterType type, std::string_view description) {
  ParameterKey k;
  k.name = name;
  k.type = type;
  k.description = description;
  return k;
}

}  // namespace

ParameterKey number_key(std::string_view name, Range range, std::string_view description) {
  ParameterKey k = make_key(name, ParameterType::number, description);
  k.range = range;
  return k;
}

ParameterKey integer_key(std::string_view name, std::uint64_t lo, std::uint64_t hi,
                         std::string_view description) {
  ParameterKey k = make_key(name, ParameterType::integer, description);
  k.integer_min = lo;
  k.integer_max = hi;
  return k;
}

ParameterKey boolean_key(std::string_view name, std::string_view description) {
  return make_key(name, ParameterType::boolean, description);
}

ParameterKey string_key(std::string_view name, std::string_view description) {
  return make_key(name, ParameterType::string, description);
}

ParameterKey vec3_key(std::string_view name, Range range, std::string_view description) {
  ParameterKey k = make_key(name, ParameterType::vec3, description);
  k.range = range;
  return k;
}

ParameterKey unit_color_key(std::string_view name, std::string_view description) {
  ParameterKey k = make_key(name, ParameterType::unit_color, description);
  k.range = kUnit;
  return k;
}

ParameterKey choice_key(std::string_view name, std::vector<std::string_view> choices,
                        std::string_view description) {
  ParameterKey k = make_key(name, ParameterType::choice, description);
  k.choices = std::move(choices);
  return k;
}

ParameterKey object_key(std::string_view name, const ParameterTable& table,
                        std::string_view description) {
  ParameterKey k = make_key(name, ParameterType::object, description);
  k.table = &table;
  return k;
}

ParameterKey objects_key(std::string_view name, const ParameterTable& table,
                         std::string_view description) {
  ParameterKey k = make_key(name, ParameterType::objects, description);
  k.table = &table;
  return k;
}

ParameterKey custom_key(std::string_view name, Range range, std::string_view description,
                        std::function<nlohmann::json(const ParameterKey&)> schema) {
  ParameterKey k = make_key(name, ParameterType::custom, description);
  k.range = range;
  k.custom_schema = std::move(schema);
  return k;
}

}  // namespace pyro
