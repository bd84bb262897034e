#include "engine/io/io_error.h"

#include <cstring>

namespace pyro {

IoError::IoError(const std::string& file, const std::string& action, int os_error)
    : std::runtime_error(file + ": cannot " + action + ": " + std::strerror(os_error)),
      file_(file),
      action_(action),
      os_error_(os_error) {}

}  // namespace pyro
