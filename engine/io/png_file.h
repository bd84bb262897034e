#pragma once
// PNG output, written durably (engine/io/durable_file.h): a failure never leaves a partial image
// under the final name.
#include <cstdint>
#include <string>
#include <vector>

namespace pyro {

// 8-bit RGB (channels 3) or RGBA (channels 4), top row first. Throws IoError naming the file and
// the OS error when it cannot be written (UserError when its folder does not exist).
void write_png(const std::string& path, int width, int height, int channels,
               const std::vector<uint8_t>& pixels);

// Linear RGBA floats to 8-bit sRGB RGB as the final pass shows them (highlights rolled off:
// engine/math/highlight_rolloff.h; alpha dropped: frames are opaque).
std::vector<uint8_t> linear_rgba_to_srgb8(const std::vector<float>& rgba, int width, int height);

struct PngImage {
  int width = 0, height = 0, channels = 0;
  std::vector<uint8_t> pixels;
};
// Reads a PNG (for tests and tools). Throws pyro::UserError naming the file on failure.
PngImage read_png(const std::string& path);

}  // namespace pyro
