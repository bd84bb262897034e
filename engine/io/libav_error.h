#pragma once
// libav's error codes (negative AVERROR values) in words, for the video reader and writer.
#include <string>

namespace pyro {

// av_strerror's text for `code`.
std::string libav_error_text(int code);

// Throws IoError naming `path` and `action`: with the errno when `code` is AVERROR(errno) (a full
// disk reads "No space left on device"), else with av_strerror's text and EIO.
[[noreturn]] void throw_libav_io_error(const std::string& path, const std::string& action, int code);

}  // namespace pyro
