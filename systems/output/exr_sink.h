#pragma once
// OpenEXR frames: each output frame scene-referred, as the linear framebuffer holds it (linear
// half-float RGBA, premultiplied alpha, before the shown frame's highlight roll-off), with a
// float view-depth channel Z when asked for (engine/io/exr_file.h writes each durably); for
// transparent frames over nothing, alpha the coverage and the colour premultiplied by it
// (transparent_frame.h): frame_NNNN.exr, or frame_NNNN_left.exr and frame_NNNN_right.exr for a
// stereo run (whatever its stereo mode: EXR holds the eyes, not the side-by-side or anaglyph
// picture made of them). Each view at the size it was rendered.
#include "systems/output/frame_sink.h"

namespace pyro {

class ExrSink : public FrameSink {
 public:
  ExrSink(bool two_views, bool depth) : two_views_(two_views), depth_(depth) {}
  std::vector<std::string> files(int index) const override;
  void write(OutputFrame& frame, const std::filesystem::path& staging) override;

 private:
  bool two_views_, depth_;
};

}  // namespace pyro
