#pragma once
// Typed, range-checked reads from a JSON parameter file (a scene, later any file of settings):
// each value is read at its place (the file and the JSON pointer, RFC 6901), checked against its
// type and range, and refused with a message that says what was expected and what was found.
// ObjectReader walks one JSON object: fields keep their defaults when a key is absent, and
// finish() refuses every key that no read asked for, with a "did you mean" suggestion.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "engine/core/enum_names.h"
#include "engine/io/parameter_range.h"
#include "engine/io/parameter_table.h"
#include "engine/io/parameter_text.h"

namespace pyro {

// Where a value sits: the file and the JSON pointer inside it.
struct Where {
  const std::string* file;
  std::string pointer;

  Where child(std::string_view key) const {
    return {file, pointer + "/" + escape_pointer_token(key)};
  }
  Where child(std::size_t index) const { return {file, pointer + "/" + std::to_string(index)}; }
  // Throws UserError(file, pointer, message).
  [[noreturn]] void fail(const std::string& message) const;
};

float read_number(const nlohmann::json& v, const Where& at, const Range& range);
// Accepts 1e6 and 3.0, refuses 2.5 and -1; exact up to 2^53 when written with a fraction or exponent.
std::uint64_t read_integer(const nlohmann::json& v, const Where& at, std::uint64_t lo, std::uint64_t hi);
glm::vec3 read_vec3(const nlohmann::json& v, const Where& at, const Range& range);
// A colour in [0, 1]: either a grey level c, meaning (c, c, c), or [r, g, b].
glm::vec3 read_unit_color(const nlohmann::json& v, const Where& at);
bool read_bool(const nlohmann::json& v, const Where& at);

// Reads the keys of one JSON object into fields whose current values are the defaults.
// Over a ParameterTable, every key asked for must be in the table (std::logic_error otherwise)
// and the reads without a range take the key's range, limits and names from the table; nested
// objects are read over the key's nested table.
class ObjectReader {
 public:
  using json = nlohmann::json;

  // Throws when `object` is not a JSON object ("expected <what>, found ...").
  ObjectReader(const json& object, Where where, std::string_view what = "an object");
  ObjectReader(const json& object, Where where, const ParameterTable& table,
               std::string_view what = "an object");
  // The reader keeps a reference to `object`: a temporary would be gone before the first read.
  ObjectReader(json&& object, Where where, std::string_view what = "an object") = delete;
  ObjectReader(json&& object, Where where, const ParameterTable& table,
               std::string_view what = "an object") = delete;

  const Where& where() const { return where_; }
  Where at(std::string_view key) const { return where_.child(key); }
  const ParameterTable* table() const { return table_; }

  // The table's entry for `key` (std::logic_error without a table or without the key, or when
  // its type is not `type`).
  const ParameterKey& key(std::string_view key, ParameterType type) const;

  // The value under `key`, or nullptr when absent. Either way `key` becomes a known key.
  const json* find(std::string_view key);

  // Reads over the table: the key's type must match the field's.
  void number(std::string_view key, float& out);
  void vec3(std::string_view key, glm::vec3& out);
  void boolean(std::string_view key, bool& out);
  template <class Int>
  void integer(std::string_view key, Int& out) {
    const ParameterKey& k = this->key(key, ParameterType::integer);
    integer(key, k.integer_min, k.integer_max, out);
  }
  // One of the key's choice names, which are E's names (engine/core/enum_names.h).
  template <class E>
  void choice(std::string_view key, E& out);

  // The value under `key`; refused as a missing key ("expected <what>") when absent.
  const json& require(std::string_view key, std::string_view what);

  void number(std::string_view key, const Range& range, float& out);

  template <class Int>
  void integer(std::string_view key, std::uint64_t lo, std::uint64_t hi, Int& out) {
    if (const json* v = find(key)) out = static_cast<Int>(read_integer(*v, at(key), lo, hi));
  }

  void vec3(std::string_view key, const Range& range, glm::vec3& out);
  void unit_color(std::string_view key, glm::vec3& out);
  void string(std::string_view key, std::string& out);

  // A nested object: `read(ObjectReader&)` fills fields, then unknown keys are refused.
  template <class F>
  void object(std::string_view key, F&& read) {
    if (const json* v = find(key)) {
      ObjectReader child = nested(*v, key, ParameterType::object, at(key), "an object");
      read(child);
      child.finish();
    }
  }

  // An array of objects, each read like object(); `read(ObjectReader&, index)`.
  template <class F>
  void objects(std::string_view key, std::string_view what, F&& read) {
    const json* v = find(key);
    if (v == nullptr) return;
    const Where array_at = at(key);
    if (!v->is_array()) array_at.fail("expected an array of objects, found " + describe(*v));
    for (std::size_t i = 0; i < v->size(); ++i) {
      ObjectReader child = nested((*v)[i], key, ParameterType::objects, array_at.child(i), what);
      read(child, i);
      child.finish();
    }
  }

  // Refuses every key of the table present in the object that applies only with other values of
  // `choice_key` than `value` (ParameterKey::only_for), naming the values it applies to.
  void refuse_keys_not_for(std::string_view choice_key, std::string_view value) const;

  // Refuses every key that no read asked for.
  void finish() const;

 private:
  // A reader of `v` over the nested table of `key` (over no table when this reader has none).
  ObjectReader nested(const json& v, std::string_view key, ParameterType type, Where where,
                      std::string_view what) const;

  const json& object_;
  Where where_;
  const ParameterTable* table_ = nullptr;
  std::vector<std::string_view> known_;
};

// A string under `key` that must be one of `names`: its index, `fallback` when absent.
std::size_t read_choice(ObjectReader& r, std::string_view key,
                        const std::vector<std::string_view>& names, std::size_t fallback);

// read_choice over E's names (engine/core/enum_names.h): the value named at `key`, `fallback`
// when the key is absent.
template <class E>
E read_enum(ObjectReader& r, std::string_view key, E fallback) {
  return enum_table<E>()[read_choice(r, key, enum_name_views<E>(), enum_index(fallback))].value;
}

template <class E>
void ObjectReader::choice(std::string_view key, E& out) {
  const ParameterKey& k = this->key(key, ParameterType::choice);
  out = enum_table<E>()[read_choice(*this, key, k.choices, enum_index(out))].value;
}

}  // namespace pyro
