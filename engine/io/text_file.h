#pragma once
// Text output (CSV, JSON). Files are written to a temporary name beside the destination
// (`path.partial`) and renamed once complete, so a reader never sees a half-written file.
#include <string>

namespace pyro {

// Writes `text` to `path` atomically. Throws pyro::UserError naming the file when it cannot be
// written (missing or read-only folder).
void write_text_file(const std::string& path, const std::string& text);

}  // namespace pyro
