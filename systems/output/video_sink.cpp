#include "systems/output/video_sink.h"

#include <stdexcept>

namespace pyro {

void VideoSink::write(OutputFrame& frame, const std::filesystem::path&) {
  const ShownImage& shown = frame.shown();
  if (!writer_) writer_ = std::make_unique<VideoWriter>(path_, shown.width, shown.height, fps_, quality_);
  writer_->add_frame(shown.rgba.data(), 4);
}

void VideoSink::finish() {
  if (!writer_) throw std::logic_error("VideoSink: finish() before any frame");
  writer_->finish();
}

}  // namespace pyro
