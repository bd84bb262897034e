#pragma once
#include <stdexcept>
#include <string>

namespace pyro::gpu {

// A failure of the graphics stack: no context, a shader that does not compile, an incomplete
// framebuffer. Messages name the file (for shaders) and carry the driver's log.
class GpuError : public std::runtime_error {
 public:
  explicit GpuError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace pyro::gpu
