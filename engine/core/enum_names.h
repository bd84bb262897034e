#pragma once
// One table of names per enumeration, written once beside the enum (components/render_modes.h,
// components/render_settings.h, ...) and read by everything that turns the enum into text or
// back: the scene loader, the command line, the viewer, the charts.
//
//   enum class Fruit { apple, pear };
//   inline constexpr EnumName<Fruit> fruit_names[] = {{Fruit::apple, "apple"}, {Fruit::pear, "pear"}};
//   constexpr const auto& enum_names(Fruit) { return fruit_names; }   // found by ADL
//
//   name_of(Fruit::pear) == "pear";  enum_from_name<Fruit>("apple") == Fruit::apple;
//   enum_name_list<Fruit>() == "\"apple\", \"pear\"" (for "expected one of ..." messages).
#include <cstddef>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pyro {

template <class E>
struct EnumName {
  E value;
  std::string_view name;
};

// The table registered for E (through the ADL function enum_names(E)).
template <class E>
constexpr const auto& enum_table() {
  return enum_names(E{});
}

// The name of `value`; throws std::invalid_argument for a value the table lacks (a table
// written incompletely: a programming error, not a user's).
template <class E>
std::string_view name_of(E value) {
  for (const EnumName<E>& entry : enum_table<E>())
    if (entry.value == value) return entry.name;
  throw std::invalid_argument("name_of: a value without a name in its enum's table");
}

template <class E>
std::optional<E> enum_from_name(std::string_view name) {
  for (const EnumName<E>& entry : enum_table<E>())
    if (entry.name == name) return entry.value;
  return std::nullopt;
}

// The place of `value` in its table (for parsers that work with indices into the names).
template <class E>
std::size_t enum_index(E value) {
  std::size_t i = 0;
  for (const EnumName<E>& entry : enum_table<E>()) {
    if (entry.value == value) return i;
    ++i;
  }
  throw std::invalid_argument("enum_index: a value without a name in its enum's table");
}

// Every name, in the table's order.
template <class E>
std::vector<std::string_view> enum_name_views() {
  std::vector<std::string_view> names;
  for (const EnumName<E>& entry : enum_table<E>()) names.push_back(entry.name);
  return names;
}

// "\"a\", \"b\", \"c\"": the accepted names, for error messages.
template <class E>
std::string enum_name_list() {
  std::string list;
  for (const EnumName<E>& entry : enum_table<E>()) {
    if (!list.empty()) list += ", ";
    list += "\"" + std::string(entry.name) + "\"";
  }
  return list;
}

// name -> value, for command-line parsers (CLI11's CheckedTransformer and IsMember).
template <class E>
std::map<std::string, E> enum_name_map() {
  std::map<std::string, E> names;
  for (const EnumName<E>& entry : enum_table<E>()) names.emplace(std::string(entry.name), entry.value);
  return names;
}

}  // namespace pyro
