#pragma once
// The keys of one object of a parameter file, written once: each key's name, JSON type, range,
// default, one-line description, enumeration names, required-ness and nested table. A reader
// (ObjectReader over a table, parameter_dictionary.h) takes the ranges and names from here, and
// the JSON Schema (parameter_schema.h) and documentation checks are derived from the same table.
//
//   static const CameraDescription d{};
//   static const ParameterTable t{"camera", "The viewpoint.", {
//       number_key("fov_y_deg", {0, 180, true, true}, "Vertical field of view, degrees.")
//           .with_default(d.fov_y_deg), ...}};
//
// Defaults are read from a default-constructed description, never written twice.
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "engine/core/enum_names.h"
#include "engine/io/parameter_range.h"

namespace pyro {

enum class ParameterType {
  number,      // a JSON number, read as a float, in `range`
  integer,     // a whole number in [integer_min, integer_max]
  boolean,
  string,
  vec3,        // 3 numbers, each in `range`
  unit_color,  // a grey level c in [0, 1] or 3 numbers each in [0, 1]
  choice,      // one of `choices`
  object,      // an object of `table`'s keys
  objects,     // an array of such objects
  custom,      // any other shape: the reader's own code; `custom_schema` describes it
};

struct ParameterTable;

struct ParameterKey {
  std::string_view name;
  ParameterType type = ParameterType::number;
  std::string_view description;
  Range range = kAnyRange;
  std::uint64_t integer_min = 0, integer_max = 0;
  std::vector<std::string_view> choices;
  bool required = false;
  std::size_t min_items = 0;              // objects: the fewest entries accepted
  const ParameterTable* table = nullptr;  // object, objects
  nlohmann::json default_value;           // null: none (or not one fixed value)
  // custom: the JSON Schema of the value, built from this key (its range, description).
  std::function<nlohmann::json(const ParameterKey&)> custom_schema;
  // A key that applies only when the choice key `only_with_key` holds one of `only_with_values`
  // (empty: always; if required, required only there); on any other choice it is refused, by
  // the reader (ObjectReader::refuse_keys_not_for) and by the schema alike.
  std::string_view only_with_key;
  std::vector<std::string_view> only_with_values;

  ParameterKey with_default(float v) const;
  ParameterKey with_default(const glm::vec3& v) const;
  template <class I>
    requires(std::is_integral_v<I> && !std::is_same_v<I, bool>)
  ParameterKey with_default(I v) const {
    return with_integer_default(static_cast<std::uint64_t>(v));
  }
  ParameterKey with_default(bool v) const;
  ParameterKey with_default(std::string_view v) const;
  // (A string literal would otherwise convert to bool before string_view.)
  ParameterKey with_default(const char* v) const { return with_default(std::string_view(v)); }
  template <class E>
    requires std::is_enum_v<E>
  ParameterKey with_default(E v) const {
    return with_default(name_of(v));
  }
  ParameterKey as_required() const;
  ParameterKey with_min_items(std::size_t n) const;
  ParameterKey only_for(std::string_view choice_key, std::vector<std::string_view> values) const;

 private:
  ParameterKey with_integer_default(std::uint64_t v) const;
};

struct ParameterTable {
  std::string_view name;         // the object's place, for messages and the schema's title
  std::string_view description;
  std::vector<ParameterKey> keys;

  // The key named `name`; std::logic_error when the table has none (a reader asking for a key
  // that its table does not declare is a programming error, caught by the tests).
  const ParameterKey& key(std::string_view key_name) const;
  const ParameterKey* find(std::string_view key_name) const;
};

ParameterKey number_key(std::string_view name, Range range, std::string_view description);
ParameterKey integer_key(std::string_view name, std::uint64_t lo, std::uint64_t hi,
                         std::string_view description);
ParameterKey boolean_key(std::string_view name, std::string_view description);
ParameterKey string_key(std::string_view name, std::string_view description);
ParameterKey vec3_key(std::string_view name, Range range, std::string_view description);
ParameterKey unit_color_key(std::string_view name, std::string_view description);
ParameterKey choice_key(std::string_view name, std::vector<std::string_view> choices,
                        std::string_view description);
template <class E>
ParameterKey enum_key(std::string_view name, std::string_view description) {
  return choice_key(name, enum_name_views<E>(), description);
}
ParameterKey object_key(std::string_view name, const ParameterTable& table,
                        std::string_view description);
ParameterKey objects_key(std::string_view name, const ParameterTable& table,
                         std::string_view description);
ParameterKey custom_key(std::string_view name, Range range, std::string_view description,
                        std::function<nlohmann::json(const ParameterKey&)> schema);

// The default as JSON: the shortest decimal that reads back as the same float.
// (null for infinity or NaN, which JSON cannot hold).
nlohmann::json float_json(float v);

}  // namespace pyro
