#pragma once
// The independent JSON Schema validator the schema tests use: Python's jsonschema
// (Debian: python3-jsonschema) through tests/tools/validate_json.py.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/test_paths.h"

namespace pyro::test {

// The validator's verdict on each file against `schema`: "valid" or "invalid POINTER: MESSAGE",
// in the order of `files`. Throws when it does not answer for every file.
inline std::vector<std::string> jsonschema_verdicts(const std::filesystem::path& schema,
                                                    const std::vector<std::filesystem::path>& files) {
  const std::filesystem::path script = std::filesystem::path(PYRO_SOURCE_DIR) / "tests/tools/validate_json.py";
  std::string command = "/usr/bin/python3 " + shell_quote(script.string()) + " " + shell_quote(schema.string());
  for (const std::filesystem::path& f : files) command += " " + shell_quote(f.string());
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), ::pclose);
  if (!pipe) throw std::runtime_error("cannot run " + command);
  std::vector<std::string> verdicts;
  char line[4096];
  while (std::fgets(line, sizeof line, pipe.get()) != nullptr) {
    std::string s = line;
    if (!s.empty() && s.back() == '\n') s.pop_back();
    verdicts.push_back(s);
  }
  if (verdicts.size() != files.size())
    throw std::runtime_error("the validator answered " + std::to_string(verdicts.size()) + " of " +
                             std::to_string(files.size()) + " files (is python3-jsonschema installed?)");
  return verdicts;
}

}  // namespace pyro::test
