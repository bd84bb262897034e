#pragma once
// Reads a whole video back into 8-bit RGB frames through libav (for tests and tools: the
// frames of a short clip are held in memory).
#include <cstdint>
#include <string>
#include <vector>

namespace pyro {

struct VideoClip {
  int width = 0, height = 0;
  double fps = 0.0;  // the stream's average frame rate
  // Every decoded frame, RGB (3 bytes a pixel), top row first.
  std::vector<std::vector<uint8_t>> frames;
  int frame_count() const { return static_cast<int>(frames.size()); }
};

// Decodes the first video stream of `path`. Throws UserError naming the file (with
// av_strerror's text) when it cannot be opened or decoded.
VideoClip read_video(const std::string& path);

}  // namespace pyro
