#pragma once
// The commands' results on standard output, checked: a write that fails (a full disk, /dev/full,
// a closed pipe) is an IoError (exit status 1 with the OS error), never a silent success with a
// short or empty file. main() also flushes and checks standard output before it returns, for
// what CLI11 prints itself (--help, --version).
#include <cerrno>
#include <cstdio>
#include <string>
#include <string_view>

#include "engine/io/io_error.h"

namespace pyro::cli {

inline void write_stdout(std::string_view text) {
  errno = 0;
  const size_t written = std::fwrite(text.data(), 1, text.size(), stdout);
  if (written != text.size() || std::fflush(stdout) != 0)
    throw IoError("standard output", "write the result", errno != 0 ? errno : EIO);
}

// A result as one JSON line (--json) or as its text for people.
template <class Json>
void write_result(const Json& json_result, const std::string& text, bool json) {
  write_stdout(json ? json_result.dump() + "\n" : text);
}

// A report of the tools (a `json` object and its `text`), as above.
template <class Report>
void write_result(const Report& report, bool json) {
  write_result(report.json, report.text, json);
}

}  // namespace pyro::cli
