#pragma once
// PNG frames: each output frame as shown (sRGB, 8-bit RGB, alpha dropped: frames are opaque; for
// transparent frames RGBA, straight alpha, over nothing: transparent_frame.h), frame_NNNN.png, or
// frame_NNNN_left.png and frame_NNNN_right.png when the shown image holds two views side by side
// (engine/io/png_file.h writes each durably).
#include "systems/output/frame_sink.h"

namespace pyro {

class PngSink : public FrameSink {
 public:
  // `two_views`: the shown images hold the left and the right view side by side.
  explicit PngSink(bool two_views) : two_views_(two_views) {}
  std::vector<std::string> files(int index) const override;
  void write(OutputFrame& frame, const std::filesystem::path& staging) override;

 private:
  bool two_views_;
};

// Writes `shown` as `stem`.png, or `stem`_left.png and `stem`_right.png (split in halves) when
// `two_views`; returns the paths written. For programs that write a single image. `channels` 3:
// RGB, alpha dropped; 4: RGBA.
std::vector<std::string> write_shown_png(const ShownImage& shown, const std::string& stem,
                                         bool two_views, int channels = 3);

}  // namespace pyro
