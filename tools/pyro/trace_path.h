#pragma once
// Checks, before any work, that a trace file can be written where the user asked.
#include <filesystem>
#include <string>

#include "engine/core/user_error.h"

namespace pyro::cli {

// Throws UserError(path, option, ...) unless `path` names a file (not a folder) in a folder
// that exists.
inline void check_trace_path(const std::string& path, const std::string& option) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw UserError(path, option, "expected a file name for the trace, found a folder");
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec))
    throw UserError(path, option, "expected the trace file's folder to exist: \"" + parent.string() + "\"");
}

}  // namespace pyro::cli
