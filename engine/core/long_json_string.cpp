#include "engine/core/long_json_string.h"

namespace pyro {

std::optional<LongJsonString> find_long_json_string(std::string_view text, std::size_t limit) {
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] != '"') {
      ++i;
      continue;
    }
    const std::size_t open = i++;
    while (i < text.size() && text[i] != '"') i += text[i] == '\\' ? 2 : 1;
    const std::size_t end = i < text.size() ? i : text.size();
    if (end - open - 1 > limit) return LongJsonString{open, end - open - 1};
    ++i;  // past the closing quote
  }
  return std::nullopt;
}

}  // namespace pyro
