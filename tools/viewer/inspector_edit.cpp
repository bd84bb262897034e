#include "tools/viewer/inspector_edit.h"

#include <algorithm>
#include <utility>

#include "engine/io/json_text_edit.h"

namespace pyro {

namespace {

bool is_index(const std::string& token) {
  return !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
}

// How many leading tokens name values present in `tree`.
size_t present_depth(const nlohmann::json& tree, const std::vector<std::string>& tokens) {
  const nlohmann::json* at = &tree;
  size_t depth = 0;
  for (const std::string& t : tokens) {
    if (at->is_object() && at->contains(t)) {
      at = &(*at)[t];
    } else if (at->is_array() && is_index(t) && std::stoull(t) < at->size()) {
      at = &(*at)[std::stoull(t)];
    } else {
      break;
    }
    ++depth;
  }
  return depth;
}

}  // namespace

InspectorEdit edit_creating_parents(const nlohmann::json& tree, const std::vector<std::string>& tokens,
                                    nlohmann::json value, bool coalesce) {
  const size_t depth = present_depth(tree, tokens);
  // The parent exists (depth >= size - 1), or the missing part holds an index: edit in place.
  size_t keep = tokens.empty() ? 0 : tokens.size() - 1;
  if (depth < keep) {
    bool all_keys = true;
    for (size_t i = depth; i < tokens.size(); ++i) all_keys = all_keys && !is_index(tokens[i]);
    if (all_keys) {
      for (size_t i = tokens.size() - 1; i > depth; --i) value = nlohmann::json{{tokens[i], std::move(value)}};
      keep = depth;
    }
  }
  std::vector<std::string> target(tokens.begin(), tokens.begin() + std::min(tokens.size(), keep + 1));
  return {json_pointer_text(target), std::move(value), coalesce};
}

}  // namespace pyro
