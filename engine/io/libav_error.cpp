#include "engine/io/libav_error.h"

#include <cerrno>

#include "engine/io/io_error.h"

extern "C" {
#include <libavutil/error.h>
}

namespace pyro {

std::string libav_error_text(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  if (av_strerror(code, text, sizeof(text)) < 0) return "libav error " + std::to_string(code);
  return text;
}

void throw_libav_io_error(const std::string& path, const std::string& action, int code) {
  // AVERROR(e) is -e for an errno e; libav's own codes are four-character tags, far below.
  const int os_error = -code;
  if (os_error > 0 && os_error < 4096) throw IoError(path, action, os_error);
  throw IoError(path, action + " (libav: " + libav_error_text(code) + ")", EIO);
}

}  // namespace pyro
