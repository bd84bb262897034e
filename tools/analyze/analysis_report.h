#pragma once
// What an analysis returns for a command to print: one JSON object (--json) and the same
// result as text for people.
#include <nlohmann/json.hpp>
#include <string>

namespace pyro {

struct AnalysisReport {
  nlohmann::json json;
  std::string text;
};

}  // namespace pyro
