#pragma once
// A helper program the command line runs (a plotting script) is missing or failed: not the
// user's argument, not a bug in pyro. main() prints what() and exits with status 1.
#include <stdexcept>
#include <string>

namespace pyro::cli {

class ExternalToolError : public std::runtime_error {
 public:
  explicit ExternalToolError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace pyro::cli
