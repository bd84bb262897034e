#pragma once
// A cheap pass over JSON text, before any parser sees it: the first string (key or value) longer
// than a limit. A parser copies every string several times (its token buffer, the key, the
// document), so refusing an absurd string first keeps the memory a file costs near its own size.
#include <cstddef>
#include <optional>
#include <string_view>

namespace pyro {

struct LongJsonString {
  std::size_t offset = 0;  // of its opening quote
  std::size_t bytes = 0;   // between the quotes, escapes as written
};

// Strings are delimited by unescaped '"' (outside a string JSON has no other quote), so for
// valid JSON this finds exactly the strings; for invalid JSON the parser's refusal follows.
std::optional<LongJsonString> find_long_json_string(std::string_view text, std::size_t limit);

}  // namespace pyro
