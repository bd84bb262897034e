#include "engine/io/parameter_dictionary.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/core/user_error.h"

namespace pyro {

using json = nlohmann::json;

void Where::fail(const std::string& message) const { throw UserError(*file, pointer, message); }

float read_number(const json& v, const Where& at, const Range& range) {
  const std::string expected = "expected a number in " + range.text();
  if (!v.is_number()) at.fail(expected + ", found " + describe(v));
  const double d = v.get<double>();
  if (!range.contains(d)) at.fail(expected + ", found " + describe(v));
  float f = static_cast<float>(d);
  // A number at a closed end that rounds just past it (0.99 is 0.99000001 in a float) is the
  // float on its side of the end: the range's own ends are always accepted.
  if (!range.contains(f) && !range.hi_open && f > range.hi) f = std::nextafter(f, -INFINITY);
  if (!range.contains(f) && !range.lo_open && f < range.lo) f = std::nextafter(f, INFINITY);
  if (!range.contains(f)) {  // e.g. 1e-50 for a positive value: rounds to 0 in a float
    at.fail(expected + ", found " + describe(v) + ", which is " + format_float(f) +
            " in single precision");
  }
  return f;
}

std::uint64_t read_integer(const json& v, const Where& at, std::uint64_t lo, std::uint64_t hi) {
  const std::string expected = "expected an integer in [" + std::to_string(lo) + ", " +
                               std::to_string(hi) + "], found " + describe(v);
  std::uint64_t u = 0;
  if (v.is_number_unsigned()) {
    u = v.get<std::uint64_t>();
  } else if (v.is_number_integer()) {
    const std::int64_t i = v.get<std::int64_t>();
    if (i < 0) at.fail(expected);
    u = static_cast<std::uint64_t>(i);
  } else if (v.is_number_float()) {  // accept 1e6 or 3.0, refuse 2.5
    const double d = v.get<double>();
    if (d != std::floor(d)) at.fail(expected + " (not a whole number)");
    if (d < 0.0 || d > 9007199254740992.0) at.fail(expected);  // beyond 2^53: not exact
    u = static_cast<std::uint64_t>(d);
  } else {
    at.fail(expected);
  }
  if (u < lo || u > hi) at.fail(expected);
  return u;
}

glm::vec3 read_vec3(const json& v, const Where& at, const Range& range) {
  if (!v.is_array() || v.size() != 3) {
    at.fail("expected an array of 3 numbers, each in " + range.text() + ", found " + describe(v));
  }
  glm::vec3 out;
  for (std::size_t i = 0; i < 3; ++i)
    out[static_cast<glm::length_t>(i)] = read_number(v[i], at.child(i), range);
  return out;
}

// A colour in [0, 1]: either a grey level c, meaning (c, c, c), or [r, g, b].
glm::vec3 read_unit_color(const json& v, const Where& at) {
  if (v.is_number()) return glm::vec3(read_number(v, at, kUnit));
  if (v.is_array()) return read_vec3(v, at, kUnit);
  at.fail("expected a grey level in [0, 1] or an array of 3 numbers each in [0, 1], found " +
          describe(v));
}

bool read_bool(const json& v, const Where& at) {
  if (!v.is_boolean()) at.fail("expected true or false, found " + describe(v));
  return v.get<bool>();
}


ObjectReader::ObjectReader(const json& object, Where where, std::string_view what)
    : object_(object), where_(std::move(where)) {
  if (!object_.is_object())
    where_.fail("expected " + std::string(what) + ", found " + describe(object_));
}

ObjectReader::ObjectReader(const json& object, Where where, const ParameterTable& table,
                           std::string_view what)
    : ObjectReader(object, std::move(where), what) {
  table_ = &table;
}

const ParameterKey& ObjectReader::key(std::string_view key, ParameterType type) const {
  if (table_ == nullptr)
    throw std::logic_error("a read of \"" + std::string(key) + "\" needs a key table");
  const ParameterKey& k = table_->key(key);
  if (k.type != type)
    throw std::logic_error("the key table \"" + std::string(table_->name) + "\" gives \"" +
                           std::string(key) + "\" another type than its reader reads");
  return k;
}

ObjectReader ObjectReader::nested(const json& v, std::string_view key, ParameterType type,
                                  Where where, std::string_view what) const {
  if (table_ == nullptr) return ObjectReader(v, std::move(where), what);
  return ObjectReader(v, std::move(where), *this->key(key, type).table, what);
}

const json* ObjectReader::find(std::string_view key) {
  if (table_ != nullptr) table_->key(key);  // throws for a key the table does not declare
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.push_back(key);
  const auto it = object_.find(key);
  return it == object_.end() ? nullptr : &*it;
}

const json& ObjectReader::require(std::string_view key, std::string_view what) {
  if (table_ != nullptr && !table_->key(key).required)
    throw std::logic_error("the key table \"" + std::string(table_->name) + "\" does not mark \"" +
                           std::string(key) + "\" required");
  const json* v = find(key);
  if (v == nullptr)
    where_.fail("missing required key " + in_quotes(key) + ": expected " + std::string(what));
  return *v;
}

void ObjectReader::number(std::string_view key, const Range& range, float& out) {
  if (const json* v = find(key)) out = read_number(*v, at(key), range);
}

void ObjectReader::vec3(std::string_view key, const Range& range, glm::vec3& out) {
  if (const json* v = find(key)) out = read_vec3(*v, at(key), range);
}

void ObjectReader::unit_color(std::string_view key, glm::vec3& out) {
  if (table_ != nullptr) this->key(key, ParameterType::unit_color);
  if (const json* v = find(key)) out = read_unit_color(*v, at(key));
}

void ObjectReader::string(std::string_view key, std::string& out) {
  if (table_ != nullptr) this->key(key, ParameterType::string);
  if (const json* v = find(key)) {
    if (!v->is_string()) at(key).fail("expected a string, found " + describe(*v));
    out = v->get<std::string>();
  }
}

void ObjectReader::number(std::string_view key, float& out) {
  number(key, this->key(key, ParameterType::number).range, out);
}

void ObjectReader::vec3(std::string_view key, glm::vec3& out) {
  vec3(key, this->key(key, ParameterType::vec3).range, out);
}

void ObjectReader::boolean(std::string_view key, bool& out) {
  this->key(key, ParameterType::boolean);
  if (const json* v = find(key)) out = read_bool(*v, at(key));
}

void ObjectReader::refuse_keys_not_for(std::string_view choice_key, std::string_view value) const {
  if (table_ == nullptr) return;
  for (const ParameterKey& k : table_->keys) {
    if (k.only_with_key != choice_key || !object_.contains(std::string(k.name))) continue;
    const auto& v = k.only_with_values;
    if (std::find(v.begin(), v.end(), value) != v.end()) continue;
    at(k.name).fail("unexpected key " + in_quotes(k.name) + " with " + in_quotes(choice_key) + ": " +
                    in_quotes(value) + "; it applies only to " + in_quotes(choice_key) + " " + quoted_list(v));
  }
}

void ObjectReader::finish() const {
  for (const auto& item : object_.items()) {
    const std::string& key = item.key();
    if (std::find(known_.begin(), known_.end(), std::string_view(key)) != known_.end()) continue;
    at(key).fail("unknown key " + in_quotes(key) + suggest(key, known_));
  }
}


// A string that must be one of `names`; returns its index.
std::size_t read_choice(ObjectReader& r, std::string_view key,
                        const std::vector<std::string_view>& names, std::size_t fallback) {
  const json* v = r.find(key);
  if (v == nullptr) return fallback;
  if (!v->is_string())
    r.at(key).fail("expected one of " + quoted_list(names) + ", found " + describe(*v));
  const std::string name = v->get<std::string>();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  std::string message = "unknown value " + in_quotes(name) + "; expected one of " + quoted_list(names);
  const std::string hint = suggest(name, names);
  if (hint.rfind("; did you mean", 0) == 0) message += hint;
  r.at(key).fail(message);
  return fallback;
}

}  // namespace pyro
