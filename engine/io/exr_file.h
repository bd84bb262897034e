#pragma once
// OpenEXR output of the engine's linear framebuffers, written durably (engine/io/durable_file.h):
// a failure never leaves a partial image under the final name. OpenEXR itself is seen only by
// exr_file.cpp.
#include <string>
#include <vector>

namespace pyro {

struct ExrImage {
  int width = 0, height = 0;
  // Linear RGBA floats, top row first, alpha premultiplied (as the framebuffers hold them and as
  // OpenEXR defines its RGBA channels): width * height * 4 values.
  std::vector<float> rgba;
  // Camera depth per pixel, top row first (width * height values), or empty for no depth.
  std::vector<float> depth;
};

// Writes R, G, B, A as HALF channels and the depth, when there is one, as the FLOAT channel "Z"
// (OpenEXR's name for depth), ZIP-compressed. Throws IoError naming the file and the OS error when
// it cannot be written, UserError when its folder does not exist, std::invalid_argument when the
// sizes disagree.
void write_exr(const std::string& path, const ExrImage& image);

// Reads an OpenEXR file's R, G, B, A (missing colour channels read 0, a missing A reads 1) and
// its Z channel when it has one (for tests and tools). Throws UserError naming the file when it
// cannot be read.
ExrImage read_exr(const std::string& path);

}  // namespace pyro
