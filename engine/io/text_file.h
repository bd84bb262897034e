#pragma once
// Text output (CSV, JSON, traces), written durably (engine/io/durable_file.h): a reader never
// sees a half-written file.
#include <string>

namespace pyro {

// Writes `text` to `path` atomically. Throws IoError naming the file and the OS error when it
// cannot be written (full disk, read-only file system), UserError when its folder is missing.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace pyro
