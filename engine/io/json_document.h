#pragma once
// JSON text -> tree, strictly: a syntax error is placed as "line L, column C", a key repeated in
// one object is refused (nlohmann would keep the last one silently) and nesting deeper than 64
// levels is refused (recursion stays bounded), each with the JSON pointer of the place.
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace pyro {

struct JsonDocument {
  nlohmann::json root;
  bool failed = false;
  std::string error_place;    // "line L, column C" or a JSON pointer
  std::string error_message;  // what was expected and what was found
};

JsonDocument parse_json_document(const std::string& text);

// "line L, column C" of the 1-based byte `position` of `text` (columns count UTF-8 characters).
std::string line_and_column(const std::string& text, std::size_t position);

}  // namespace pyro
