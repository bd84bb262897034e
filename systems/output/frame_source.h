#pragma once
// What the output phase reads a frame back from: the runtime that drew it (SceneRuntime), or a
// test's or an embedding program's own source.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace pyro {

// The composed frame as it is shown: highlights rolled off, upscaled when the frame scale is
// below 1, sRGB-encoded RGBA8, row 0 at the top. In left-right stereo it holds both views side by
// side, the left view in the left half.
struct ShownImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

// One view of the last drawn frame, scene-referred: linear RGBA floats (premultiplied alpha)
// with the particle layers composited, before the shown frame's highlight roll-off and sRGB
// encoding, at the size the view was rendered, row 0 at the top. `depth`, when asked for: per
// pixel the view depth (distance along the view axis) of the opaque geometry, +infinity where
// there is none (particles write no depth).
struct LinearView {
  int width = 0, height = 0;
  std::vector<float> rgba;
  std::vector<float> depth;
};

// Transparent frames (systems/output/transparent_frame.h): the background colour the frames were
// composed over, as they hold it where nothing covers it, and their alpha is the coverage.
struct FrameBackground {
  std::array<float, 3> linear{};  // the linear views' colour (LinearView::rgba)
  std::array<float, 3> shown{};   // the shown image's, sRGB-encoded, in [0, 1]
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // The last drawn frame as shown (one GPU-to-host transfer).
  virtual ShownImage read_shown() = 0;
  // Every view of the last drawn frame, linear (one view, or the left and the right eye).
  virtual std::vector<LinearView> read_linear(bool with_depth) = 0;
  // Whether the shown image holds two views side by side (left-right stereo).
  virtual bool shown_side_by_side() = 0;
  // For transparent frames, the background they were composed over (their alpha the coverage);
  // nullopt: opaque frames, alpha 1.
  virtual std::optional<FrameBackground> transparent_background() { return std::nullopt; }
};

}  // namespace pyro
