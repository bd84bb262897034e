#pragma once
// The JSON object a `pyro ... --json` command prints as its last line.
#include <string>

#include <nlohmann/json.hpp>

namespace pyro::test {

inline nlohmann::json last_json_line(const std::string& out) {
  const auto end = out.find_last_not_of('\n');
  const auto start = out.rfind('\n', end);
  const size_t from = start == std::string::npos ? 0 : start + 1;
  return nlohmann::json::parse(out.substr(from, end + 1 - from));
}

}  // namespace pyro::test
